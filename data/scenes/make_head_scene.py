#!/usr/bin/env python3
"""Writes a normal-mapped, textured head (issue 39: "a normal-mapped textured
head under an HDRI"): data/meshes/head.off with cylindrical texture
coordinates about its vertical axis (the seam at the back of the head), a
skin-toned base colour with a faint mottle and a tangent-space normal map of
pores and fine creases (OpenGL convention, green up), as DIR/head.obj +
head.mtl + head_albedo.png + head_normal.png. The head's own units; render
it at a real size, e.g.

    python3 data/scenes/make_head_scene.py /tmp/head
    tsis render --mesh /tmp/head/head.obj --size-mm 250 --material skin1 \\
        --env data/env/sky.hdr --background env --eye -420,60,300 --target 0,10,0

(the material's colour comes from the texture, its mean free path from
skin1: an OBJ has none).
"""
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_textured_scene import png  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SIZE = 512  # texture side


def read_off(path):
    tokens = [line.split() for line in open(path) if line.strip() and not line.startswith("#")]
    nv, nf = int(tokens[1][0]), int(tokens[1][1])
    verts = [tuple(float(t) for t in tokens[2 + i][:3]) for i in range(nv)]
    faces = [tuple(int(t) for t in tokens[2 + nv + i][1:]) for i in range(nf)]
    return verts, faces


def close_holes(verts, faces):
    """The scan's holes (its eyes: edges with one face) each closed by a fan
    about its loop's centroid, wound as the faces around it."""
    count = {}
    for face in faces:
        for a, b in zip(face, face[1:] + face[:1]):
            count[(a, b)] = count.get((a, b), 0) + 1
    # A boundary edge a->b has no b->a; the hole's loop runs b->a.
    nxt = {b: a for (a, b) in count if (b, a) not in count}
    verts, faces = list(verts), list(faces)
    while nxt:
        start = next(iter(nxt))
        loop, v = [], start
        while v in nxt:
            loop.append(v)
            v = nxt.pop(v)
        centre = tuple(sum(verts[i][k] for i in loop) / len(loop) for k in range(3))
        verts.append(centre)
        c = len(verts) - 1
        faces += [(loop[i], loop[(i + 1) % len(loop)], c) for i in range(len(loop))]
    return verts, faces


def height_field():
    """Pores (small round dimples on a jittered grid) and a few long shallow
    creases, as heights in [−1, 1] over the texture, tiled in u."""
    rng = random.Random(7)
    h = [[0.0] * SIZE for _ in range(SIZE)]
    cell = 8
    for gy in range(0, SIZE, cell):
        for gx in range(0, SIZE, cell):
            cx, cy = gx + rng.uniform(1, cell - 1), gy + rng.uniform(1, cell - 1)
            r = rng.uniform(1.0, 2.2)
            for y in range(int(cy - 3), int(cy + 4)):
                for x in range(int(cx - 3), int(cx + 4)):
                    d2 = (x - cx) ** 2 + (y - cy) ** 2
                    if 0 <= y < SIZE:
                        h[y][x % SIZE] -= 0.8 * math.exp(-d2 / (r * r))
    for _ in range(40):
        y0, x0 = rng.uniform(0, SIZE), rng.uniform(0, SIZE)
        angle, length = rng.uniform(-0.3, 0.3), rng.uniform(30, 90)
        for t in range(int(length)):
            x, y = x0 + t * math.cos(angle), y0 + t * math.sin(angle)
            for dy in range(-2, 3):
                yy = int(y) + dy
                if 0 <= yy < SIZE:
                    h[yy][int(x) % SIZE] -= 0.5 * math.exp(-dy * dy / 1.5)
    return h


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    verts, faces = read_off(os.path.join(ROOT, "data", "meshes", "head.off"))
    # The scan's faces wind inwards (negative signed volume): turned, so
    # that its normals point out and the lit side takes the light.
    volume = 0.0
    for face in faces:
        a = verts[face[0]]
        for b, c in zip((verts[i] for i in face[1:-1]), (verts[i] for i in face[2:])):
            volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                       a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
    if volume < 0:
        faces = [tuple(reversed(face)) for face in faces]
    verts, faces = close_holes(verts, faces)
    lo = [min(v[i] for v in verts) for i in range(3)]
    hi = [max(v[i] for v in verts) for i in range(3)]
    cx, cz = (lo[0] + hi[0]) / 2, (lo[2] + hi[2]) / 2

    def uv(p):
        # u about the vertical axis from the back of the head (+x here: the
        # face looks along −x), v up.
        u = (math.atan2(p[2] - cz, -(p[0] - cx)) / (2 * math.pi)) % 1.0
        return u, (p[1] - lo[1]) / (hi[1] - lo[1])

    h = height_field()
    strength = 1.6  # slope scale of the heights

    def normal_pixel(x, y):
        dx = h[y][(x + 1) % SIZE] - h[y][(x - 1) % SIZE]
        dy = h[min(y + 1, SIZE - 1)][x] - h[max(y - 1, 0)][x]
        # Row 0 is the top (v = 1): +v is −y in the image.
        n = (-strength * dx, strength * dy, 2.0)
        s = math.sqrt(sum(c * c for c in n))
        return tuple(int(round(255 * (0.5 + 0.5 * c / s))) for c in n)

    rng = random.Random(3)
    mottle = [[rng.uniform(-1, 1) for _ in range(SIZE // 16)] for _ in range(SIZE // 16)]

    def albedo_pixel(x, y):
        m = mottle[y // 16][x // 16]
        base = (222, 170, 140)
        return tuple(max(0, min(255, int(c * (1 + 0.04 * m)))) for c in base)

    png(os.path.join(out, "head_normal.png"), SIZE, SIZE, normal_pixel)
    png(os.path.join(out, "head_albedo.png"), SIZE, SIZE, albedo_pixel)
    with open(os.path.join(out, "head.mtl"), "w") as f:
        f.write("newmtl skin\nKd 1 1 1\nmap_Kd head_albedo.png\nnorm head_normal.png\nNi 1.4\n"
                "Pr 0.45\n")
    with open(os.path.join(out, "head.obj"), "w") as f:
        f.write("mtllib head.mtl\nusemtl skin\n")
        for p in verts:
            f.write("v %.6f %.6f %.6f\n" % p)
        k = 0
        for face in faces:
            uvs = [uv(verts[i]) for i in face]
            # A face across the seam: its small u's one turn on (the
            # texture repeats in u).
            if max(u for u, _ in uvs) - min(u for u, _ in uvs) > 0.5:
                uvs = [(u + 1 if u < 0.5 else u, v) for u, v in uvs]
            for u, v in uvs:
                f.write("vt %.6f %.6f\n" % (u, v))
            f.write("f " + " ".join("%d/%d" % (i + 1, k + j + 1) for j, i in enumerate(face)) +
                    "\n")
            k += len(face)
    print("wrote", os.path.join(out, "head.obj"))


if __name__ == "__main__":
    main()
