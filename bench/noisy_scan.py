#!/usr/bin/env python3
"""A noisy scan for the atlas builder's worst case (issue 25 item 3).

Usage: bench/noisy_scan.py IN.off OUT.ply [LEVELS] [NOISE] [SEED]

Subdivides every triangle of IN.off into four (edge midpoints) LEVELS times
(default 2: bunny00's 75K triangles become 1.2M) and moves each vertex along
its normal by uniform noise of NOISE (default 0.002) times the bounding box
diagonal — the high-frequency relief of a real scan that a clean mesh lacks.
Writes a binary little-endian PLY. Deterministic for a SEED (default 1).
Plain Python (no NumPy): about a minute for 1.2M triangles.
"""
import math
import random
import struct
import sys


def read_off(path):
    with open(path) as f:
        words = f.read().split()
    if words[0] != "OFF":
        sys.exit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    vertices = []
    for _ in range(nv):
        vertices.append(tuple(float(w) for w in words[at:at + 3]))
        at += 3
    faces = []
    for _ in range(nf):
        n = int(words[at])
        idx = [int(w) for w in words[at + 1:at + 1 + n]]
        at += 1 + n
        for k in range(1, n - 1):  # polygons as fans
            faces.append((idx[0], idx[k], idx[k + 1]))
    return vertices, faces


def subdivide(vertices, faces):
    midpoint = {}

    def mid(a, b):
        key = (a, b) if a < b else (b, a)
        if key not in midpoint:
            pa, pb = vertices[a], vertices[b]
            vertices.append(tuple(0.5 * (pa[i] + pb[i]) for i in range(3)))
            midpoint[key] = len(vertices) - 1
        return midpoint[key]

    out = []
    for a, b, c in faces:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return vertices, out


def vertex_normals(vertices, faces):
    normals = [[0.0, 0.0, 0.0] for _ in vertices]
    for a, b, c in faces:
        pa, pb, pc = vertices[a], vertices[b], vertices[c]
        u = [pb[i] - pa[i] for i in range(3)]
        v = [pc[i] - pa[i] for i in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        for k in (a, b, c):
            for i in range(3):
                normals[k][i] += n[i]
    for n in normals:
        length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2) or 1.0
        for i in range(3):
            n[i] /= length
    return normals


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    levels = int(sys.argv[3]) if len(sys.argv) > 3 else 2
    noise = float(sys.argv[4]) if len(sys.argv) > 4 else 0.002
    rng = random.Random(int(sys.argv[5]) if len(sys.argv) > 5 else 1)
    vertices, faces = read_off(sys.argv[1])
    for _ in range(levels):
        vertices, faces = subdivide(vertices, faces)
    lo = [min(p[i] for p in vertices) for i in range(3)]
    hi = [max(p[i] for p in vertices) for i in range(3)]
    amplitude = noise * math.sqrt(sum((hi[i] - lo[i]) ** 2 for i in range(3)))
    normals = vertex_normals(vertices, faces)
    moved = []
    for p, n in zip(vertices, normals):
        d = rng.uniform(-amplitude, amplitude)
        moved.append((p[0] + d * n[0], p[1] + d * n[1], p[2] + d * n[2]))
    with open(sys.argv[2], "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\n"
                 f"element vertex {len(moved)}\nproperty float x\nproperty float y\n"
                 f"property float z\nelement face {len(faces)}\n"
                 "property list uchar int vertex_indices\nend_header\n").encode())
        f.write(b"".join(struct.pack("<3f", *p) for p in moved))
        f.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))
    print(f"{sys.argv[2]}: {len(moved)} vertices, {len(faces)} triangles, noise ±{amplitude:.3g}")


if __name__ == "__main__":
    main()
