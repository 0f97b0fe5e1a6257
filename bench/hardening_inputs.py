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

# Issue 40 (hostile assets), in h40/: a textured quad as OBJ + .mtl and as
# glTF, whose texture names a FIFO, a device, a file outside the folder, a
# header that declares a huge image; materials with values out of range;
# libraries of many materials; exporters' quirks.
import zlib  # noqa: E402

h40 = os.path.join(out, "h40")
os.makedirs(os.path.join(h40, "a"), exist_ok=True)


def png(w, h, rows=None, colour=2):
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    body = chunk(b"IDAT", zlib.compress(rows)) if rows is not None else chunk(b"IDAT", b"\x78\x01")
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, colour, 0, 0, 0))
            + body + chunk(b"IEND", b""))


def put(name, data):
    with open(os.path.join(h40, name), "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)


# A 2x2 texture (RGB 188), and an RGBA one of alpha 0 (colour 188 kept).
put("a/tex.png", png(2, 2, b"\0" + bytes([188] * 6) + b"\0" + bytes([188] * 6)))
put("a/alpha0.png", png(2, 2, (b"\0" + bytes([188, 188, 188, 0] * 2)) * 2, colour=6))
put("outside.png", png(2, 2, b"\0" + bytes([188] * 6) + b"\0" + bytes([188] * 6)))
put("a/huge.png", png(16384, 16384))  # a header alone: 16384^2 declared
jpeg = (b"\xff\xd8\xff\xdb\x00\x43\x00" + b"\x01" * 64 + b"\xff\xc0\x00\x11\x08" +
        struct.pack(">HH", 16000, 16000) + b"\x03\x01\x11\x00\x02\x11\x00\x03\x11\x00" +
        b"\xff\xda\x00\x0c\x03\x01\x00\x02\x00\x03\x00\x00\x3f\x00" + b"\0" * 800 + b"\xff\xd9")
put("a/huge.jpg", jpeg)
put("sky_huge.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8192 +X 16384\n" + b"\0" * 8)
put("sky_huge.png", png(16384, 8192))
# An 8-bit sky of one grey (188) and the same radiance as a float file's
# value would be read linear: 188/255 = 0.737 against sRGB's 0.503.
put("sky188.png", png(64, 32, (b"\0" + bytes([188] * 64 * 3)) * 32))
for name, target in (("a/fifo.png", None), ("a/zero.png", "/dev/zero"),
                     ("a/urandom.png", "/dev/urandom"), ("a/link_out.png", "../outside.png")):
    p = os.path.join(h40, name)
    if os.path.lexists(p):
        os.remove(p)
    if target is None:
        os.mkfifo(p)
    else:
        os.symlink(target, p)
if os.path.lexists(os.path.join(h40, "sky_fifo.hdr")):
    os.remove(os.path.join(h40, "sky_fifo.hdr"))
os.mkfifo(os.path.join(h40, "sky_fifo.hdr"))

quad_obj = "mtllib {lib}\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n" \
           "usemtl m\nf 1/1 2/2 3/3 4/4\n"


def obj_case(name, mtl, lib=None):
    lib = lib or name + ".mtl"
    put("a/%s.obj" % name, quad_obj.format(lib=lib))
    put("a/" + lib, mtl)


for name, tex in (("mtl_fifo", "fifo.png"), ("mtl_zero", "zero.png"),
                  ("mtl_urandom", "/dev/urandom"), ("mtl_dotdot", "../outside.png"),
                  ("mtl_absolute", os.path.abspath(os.path.join(h40, "outside.png"))),
                  ("mtl_link_out", "link_out.png"), ("mtl_huge_png", "huge.png"),
                  ("mtl_huge_jpg", "huge.jpg"), ("mtl_alpha0", "alpha0.png")):
    obj_case(name, "newmtl m\nKd 1 1 1\nmap_Kd %s\n" % tex)
obj_case("mtl_bom", "\ufeffnewmtl m\nKd 0.5 0.5 0.5\n")
obj_case("mtl_ni1", "newmtl m\nKd 0.5 0.5 0.5\nNi 1.000000\n")
os.makedirs(os.path.join(h40, "a", "my  maps"), exist_ok=True)
put("a/my  maps/tex  2.png", png(2, 2, b"\0" + bytes([188] * 6) + b"\0" + bytes([188] * 6)))
obj_case("mtl_spaces", "newmtl m\nKd 1 1 1\nmap_Kd my  maps/tex  2.png\n")
put("a/mtl_lib_outside.obj", quad_obj.format(lib="../outside.mtl"))
put("outside.mtl", "newmtl m\nKd 0.2 0.8 0.2\n")
# 100,000 materials, one used; 49 unused of 50.
obj_case("mtl_100k", "".join("newmtl m%d\nKd 0.5 0.5 0.5\n" % i for i in range(100000)) +
         "newmtl m\nKd 0.5 0.5 0.5\n")
obj_case("mtl_50", "".join("newmtl u%d\nKd 0.%d 0.5 0.5\n" % (i, i % 9 + 1) for i in range(49)) +
         "newmtl m\nKd 0.5 0.5 0.5\n")

qpos = struct.pack("<12f", -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0)
quv = struct.pack("<8f", 0, 1, 1, 1, 1, 0, 0, 0)
qidx = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
qbuf = qpos + quv + qidx


def quad_gltf(materials, images=None, textures=None, primitives_material=0):
    g = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1},
                                    "indices": 2, "material": primitives_material}]}],
        "buffers": [{"byteLength": len(qbuf), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(qbuf).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [-1, -1, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                      {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
        "materials": materials,
    }
    if images:
        g["images"] = images
        g["textures"] = textures or [{"source": 0}]
    return g


def gltf_case(name, materials, **kw):
    with open(os.path.join(h40, "a", name + ".gltf"), "w") as f:
        json.dump(quad_gltf(materials, **kw), f, separators=(",", ":"))


textured = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
for name, uri in (("gltf_fifo", "fifo.png"), ("gltf_zero", "zero.png"),
                  ("gltf_urandom", "urandom.png"), ("gltf_dotdot", "../outside.png"),
                  ("gltf_link_out", "link_out.png"), ("gltf_huge_png", "huge.png"),
                  ("gltf_percent", "my%20%20maps/tex%20%202.png")):
    gltf_case(name, textured, images=[{"uri": uri}])
gltf_case("gltf_1000", [{}] * 1000)
gltf_case("gltf_factor_typo", [{"pbrMetallicRoughness": {"baseColorFactor": "0.8 0.2 0.2 1"}}])
for name, ext in (("sigma_1e300", {"sigma_s": [1e300] * 3, "sigma_a": [1, 1, 1]}),
                  ("sigma_1e-300", {"sigma_s": [1e-300] * 3, "sigma_a": [1e-300] * 3}),
                  ("mfp_1e-300", {"albedo": [0.5, 0.5, 0.5], "mfp": [1e-300] * 3})):
    gltf_case(name, [{"extras": {"tsis": ext}}])
gltf_case("atten_1e-300", [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.5, 0.5, 1]},
                            "extensions": {"KHR_materials_volume": {
                                "attenuationDistance": 1e-300,
                                "attenuationColor": [0.5, 0.5, 0.5]}}}])
