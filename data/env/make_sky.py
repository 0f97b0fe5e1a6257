#!/usr/bin/env python3
"""Writes the shipped environment map data/env/sky.hdr (tsis --env): a 256x128
lat-long Radiance RGBE image, radiance in W/(mm^2 sr), tsis' convention
(scene/environment.h): row 0 straight up, the centre column looking along -z
(behind the object, seen from the default camera).

A sky gradient (blue zenith, white horizon), a dim ground and a sun disc of
2.5 degrees radius, 30 degrees up, behind the object and a little to the
right, giving 1.5 W/mm^2 at normal incidence (the default back light gives
about 1): thin parts glow against it. The sky alone gives an upward plane
about 0.3 W/mm^2. Pure Python (no numpy), deterministic: the same bytes on
every run.

usage: make_sky.py [OUT.hdr]   (default: sky.hdr beside this script)
"""
import math
import os
import sys

W, H = 256, 128
SUN_ELEVATION, SUN_AZIMUTH = math.radians(30.0), math.radians(20.0)  # azimuth from -z towards +x
SUN_RADIUS = math.radians(2.5)
SUN_IRRADIANCE = 1.5


def direction(u, v):
    theta, phi = math.pi * v, 2.0 * math.pi * (u - 0.5)
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))


def sky(d):
    up = d[1]
    if up < 0.0:  # ground: dim, warm, darker straight down
        g = 0.035 * (1.0 + up * 0.5)
        return (g, 0.85 * g, 0.7 * g)
    t = up ** 0.5  # horizon white to zenith blue
    horizon, zenith = (0.13, 0.13, 0.13), (0.04, 0.07, 0.14)
    return tuple(h + (z - h) * t for h, z in zip(horizon, zenith))


def rgbe(rgb):
    m = max(rgb)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    e = math.frexp(m)[1]
    scale = math.ldexp(1.0, 8 - e)  # mantissa * 256 / 2^e
    return bytes([min(255, int(c * scale)) for c in rgb] + [e + 128])


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "sky.hdr")
    sun = (math.cos(SUN_ELEVATION) * math.sin(SUN_AZIMUTH), math.sin(SUN_ELEVATION),
           -math.cos(SUN_ELEVATION) * math.cos(SUN_AZIMUTH))
    sun_solid_angle = 2.0 * math.pi * (1.0 - math.cos(SUN_RADIUS))
    sun_radiance = SUN_IRRADIANCE / sun_solid_angle
    body = bytearray()
    for y in range(H):
        for x in range(W):
            # 4x4 supersampling per texel, so the disc's edge is antialiased.
            acc = [0.0, 0.0, 0.0]
            for sy in range(4):
                for sx in range(4):
                    d = direction((x + (sx + 0.5) / 4) / W, (y + (sy + 0.5) / 4) / H)
                    c = sky(d)
                    if sum(a * b for a, b in zip(d, sun)) > math.cos(SUN_RADIUS):
                        c = (sun_radiance, 0.95 * sun_radiance, 0.85 * sun_radiance)
                    acc = [a + b / 16.0 for a, b in zip(acc, c)]
            body += rgbe(acc)
    with open(out, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (H, W))
        f.write(body)


if __name__ == "__main__":
    main()
