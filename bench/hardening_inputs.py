#!/usr/bin/env python3
"""Writes the inputs of issue 22's reproductions (items 3, 4, 8) into DIR.

Usage: bench/hardening_inputs.py DIR

  multiparent.gltf        25 levels of two nodes, each the parent of both below
                          (forbidden; 2^25 instances if followed), 3 kB
  instanced.gltf          3,000 nodes x 3,000 one-triangle primitives sharing an
                          accessor (legal; 9 M triangles)
  escape/sub/*.gltf       buffers named '../quad.bin' and by absolute path
  dup<N>.obj              one triangle N times (N = 3000, 6000, 30000, 100000)
  dupperm<N>.obj          the same, corners in every order (half of them reversed)
  dupeps<N>.obj           N copies with their own corners, copy i moved by i·1e-7
"""
import base64
import json
import os
import struct
import sys

out = sys.argv[1]
os.makedirs(out, exist_ok=True)

# One triangle (3 float positions, 3 ushort indices).
pos = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
idx = struct.pack("<3H", 0, 1, 2) + b"\0\0"
buf = pos + idx


def gltf(nodes, roots, primitives, uri=None):
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": roots}],
        "nodes": nodes,
        "meshes": [{"primitives": primitives}],
        "buffers": [{"byteLength": len(buf),
                     "uri": uri or "data:application/octet-stream;base64," +
                     base64.b64encode(buf).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
    }


prim = {"attributes": {"POSITION": 0}, "indices": 1}


def write(name, obj):
    with open(os.path.join(out, name), "w") as f:
        json.dump(obj, f, separators=(",", ":"))


levels = 25
nodes = []
for i in range(2 * levels):
    nxt = (i // 2 + 1) * 2
    nodes.append({"children": [nxt, nxt + 1]} if i // 2 + 1 < levels else {"mesh": 0})
write("multiparent.gltf", gltf(nodes, [0, 1], [prim]))

n = 3000
write("instanced.gltf", gltf([{"mesh": 0} for _ in range(n)], list(range(n)), [prim] * n))

os.makedirs(os.path.join(out, "escape", "sub"), exist_ok=True)
with open(os.path.join(out, "escape", "quad.bin"), "wb") as f:
    f.write(buf)
write("escape/sub/dotdot.gltf", gltf([{"mesh": 0}], [0], [prim], "../quad.bin"))
write("escape/sub/absolute.gltf",
      gltf([{"mesh": 0}], [0], [prim], os.path.abspath(os.path.join(out, "escape", "quad.bin"))))

for n in (3000, 6000, 30000, 100000):
    with open(os.path.join(out, "dup%d.obj" % n), "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\n" + "f 1 2 3\n" * n)
    orders = ["1 2 3", "2 3 1", "3 1 2", "1 3 2", "3 2 1", "2 1 3"]
    with open(os.path.join(out, "dupperm%d.obj" % n), "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\n")
        f.write("".join("f %s\n" % orders[i % 6] for i in range(n)))
    with open(os.path.join(out, "dupeps%d.obj" % n), "w") as f:
        for i in range(n):
            e = 1e-7 * i
            f.write("v %g %g 0\nv %g %g 0\nv %g %g %g\n" % (e, 0, 1 + e, 0, 0, 1 - e, e))
        f.write("".join("f %d %d %d\n" % (3 * i + 1, 3 * i + 2, 3 * i + 3) for i in range(n)))
