#!/usr/bin/env python3
"""Writes a glTF of a textured UV sphere whose surface maps vary its material
(issue 39: a metallic-roughness texture and a mean free path texture through
extras.tsis), as DIR/maps.gltf + maps.bin + maps_roughness.png + maps_mfp.png:

* the metallic-roughness texture's G channel (× roughnessFactor 1) is R =
  0.1 on the upper half and 0.8 on the lower half, so a light's highlight
  and the sky's reflection are sharp above the equator and broad below;
* extras.tsis.mfp_texture scales the material's mean free path (2.4, 1.2,
  0.6 mm) by 1 and 1/8 in eight stripes around the sphere (the mean of the
  texel's r, g, b), so the stripes of long mean free path are softer and
  more translucent.

Render it at a real size, back-lit, e.g.

    python3 data/scenes/make_maps_scene.py /tmp/maps
    tsis render --mesh /tmp/maps/maps.gltf --size-mm 40 \\
        --light point:-30,10,-40:400,400,400 --light dir:0.3,-1,-0.5:0.3,0.3,0.3 -o maps.png
"""
import json
import math
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_textured_scene import png  # noqa: E402

RINGS, SEGMENTS = 48, 96


def sphere():
    """Positions, normals, texture coordinates (u around, v down from the
    north pole) and triangle indices of a unit UV sphere, its seam doubled."""
    pos, uv, idx = [], [], []
    for i in range(RINGS + 1):
        theta = math.pi * i / RINGS
        for j in range(SEGMENTS + 1):
            phi = 2 * math.pi * j / SEGMENTS
            pos.append((math.sin(theta) * math.cos(phi), math.cos(theta),
                        -math.sin(theta) * math.sin(phi)))
            uv.append((j / SEGMENTS, i / RINGS))
    for i in range(RINGS):
        for j in range(SEGMENTS):
            a = i * (SEGMENTS + 1) + j
            b = a + SEGMENTS + 1
            if i > 0:
                idx.append((a, b, a + 1))
            if i < RINGS - 1:
                idx.append((a + 1, b, b + 1))
    return pos, pos, uv, idx


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    pos, nrm, uv, idx = sphere()
    blob = b"".join(struct.pack("<3f", *p) for p in pos)
    blob += b"".join(struct.pack("<3f", *n) for n in nrm)
    blob += b"".join(struct.pack("<2f", *t) for t in uv)
    blob += b"".join(struct.pack("<3I", *t) for t in idx)
    with open(os.path.join(out, "maps.bin"), "wb") as f:
        f.write(blob)
    n, t = len(pos), len(idx)
    # G: R = 0.1 above the equator (image top), 0.8 below; R and B unused.
    png(os.path.join(out, "maps_roughness.png"), 64, 64,
        lambda x, y: (0, round(255 * (0.1 if y < 32 else 0.8)), 0))
    # Eight stripes around: mean free path × 1/8 and × 1 (a grey map).
    png(os.path.join(out, "maps_mfp.png"), 64, 8,
        lambda x, y: (lambda v: (v, v, v))(round(255 * (0.125 if (x // 8) % 2 == 0 else 1.0))))
    gltf = {
        "asset": {"version": "2.0", "generator": "tsis data/scenes/make_maps_scene.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
            "indices": 3, "material": 0}]}],
        "materials": [{
            "name": "striped skin",
            "pbrMetallicRoughness": {"baseColorFactor": [0.85, 0.6, 0.5, 1], "metallicFactor": 0,
                                     "roughnessFactor": 1,
                                     "metallicRoughnessTexture": {"index": 0}},
            "extras": {"tsis": {"mfp": [2.4, 1.2, 0.6], "mfp_texture": {"index": 1}}}}],
        "textures": [{"source": 0}, {"source": 1}],
        "images": [{"uri": "maps_roughness.png"}, {"uri": "maps_mfp.png"}],
        "buffers": [{"uri": "maps.bin", "byteLength": len(blob)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 12 * n},
            {"buffer": 0, "byteOffset": 12 * n, "byteLength": 12 * n},
            {"buffer": 0, "byteOffset": 24 * n, "byteLength": 8 * n},
            {"buffer": 0, "byteOffset": 32 * n, "byteLength": 12 * t}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3",
             "min": [-1, -1, -1], "max": [1, 1, 1]},
            {"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": n, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5125, "count": 3 * t, "type": "SCALAR"}],
    }
    with open(os.path.join(out, "maps.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)


if __name__ == "__main__":
    main()
