#!/usr/bin/env python3
"""Writes a small textured two-object scene (docs/guide/scenes-and-materials.md "Scenes and materials"):
a wax-like tile with a checker texture (map_Kd) beside a jade sphere (Kd only),
as DIR/two_objects.obj + .mtl + checker.png. Units: millimetres.

    python3 data/scenes/make_textured_scene.py DIR
"""
import math
import os
import struct
import sys
import zlib


def png(path, width, height, pixel):
    """An 8-bit RGB PNG of pixel(x, y) -> (r, g, b) in 0..255, row 0 = top."""
    raw = b"".join(b"\x00" + bytes(c for x in range(width) for c in pixel(x, y))
                   for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def checker(x, y):
    # 8 x 8 squares: a warm ivory and a deep red, with a thin dark grid.
    if x % 32 < 2 or y % 32 < 2:
        return (40, 30, 25)
    return (235, 220, 190) if (x // 32 + y // 32) % 2 == 0 else (170, 35, 30)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    png(os.path.join(out, "checker.png"), 256, 256, checker)
    with open(os.path.join(out, "two_objects.mtl"), "w") as f:
        f.write("newmtl tile\nKd 1 1 1\nmap_Kd checker.png\nNi 1.4\n\n"
                "newmtl jade\nKd 0.35 0.75 0.45\nNi 1.6\n")
    v, vt, faces = [], [], []

    def vert(p, uv):
        v.append(p)
        vt.append(uv)
        return len(v)

    # The tile: a 24 x 24 x 5 mm box centred at x = -14, its top textured.
    x0, x1, y0, y1, z0, z1 = -26.0, -2.0, -2.5, 2.5, -12.0, 12.0
    corners = lambda u, w, h: (x0 + u * (x1 - x0), y0 + h * (y1 - y0), z0 + w * (z1 - z0))
    quads = [  # (corner function of (s, t), counter-clockwise from outside)
        lambda s, t: corners(s, 1 - t, 1),      # top (+y)
        lambda s, t: corners(s, t, 0),          # bottom
        lambda s, t: corners(s, 1, t),          # front (+z)
        lambda s, t: corners(1 - s, 0, t),      # back
        lambda s, t: corners(1, 1 - s, t),      # right (+x)
        lambda s, t: corners(0, s, t),          # left
    ]
    for q in quads:
        a = vert(q(0, 0), (0, 0)); b = vert(q(1, 0), (1, 0))
        c = vert(q(1, 1), (1, 1)); d = vert(q(0, 1), (0, 1))
        faces.append(("tile", (a, b, c)))
        faces.append(("tile", (a, c, d)))
    # The sphere: radius 8 mm at x = +12, a UV sphere.
    rings, segs, r, cx = 32, 64, 8.0, 12.0
    grid = {}
    for i in range(rings + 1):
        th = math.pi * i / rings
        for j in range(segs + 1):
            ph = 2 * math.pi * j / segs
            grid[i, j] = vert((cx + r * math.sin(th) * math.cos(ph), r * math.cos(th),
                               -r * math.sin(th) * math.sin(ph)), (j / segs, 1 - i / rings))
    for i in range(rings):
        for j in range(segs):
            a, b, c, d = grid[i, j], grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]
            if i > 0:
                faces.append(("jade", (a, b, d)))
            if i < rings - 1:
                faces.append(("jade", (b, c, d)))
    with open(os.path.join(out, "two_objects.obj"), "w") as f:
        f.write("mtllib two_objects.mtl\n")
        for p in v:
            f.write("v %.6f %.6f %.6f\n" % p)
        for uv in vt:
            f.write("vt %.6f %.6f\n" % uv)
        current = None
        for name, (a, b, c) in faces:
            if name != current:
                f.write("o %s\nusemtl %s\n" % (name, name))
                current = name
            f.write("f %d/%d %d/%d %d/%d\n" % (a, a, b, b, c, c))


if __name__ == "__main__":
    main()
