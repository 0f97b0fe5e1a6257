#!/usr/bin/env python3
"""Mitsuba 3 reference numbers for tsis' volumetric method (issue 15, item 2).

Renders, with Mitsuba 3's volpath (pip install mitsuba; never used by the
build or CI), scenes that both Mitsuba and tsis' volumetric walk can sample: a
unit sky (constant emitter) around a dielectric object filled with a
homogeneous isotropic medium (σs = σs', σa, η; smooth dielectric boundary),
seen through 1×1-pixel orthographic windows (box filter), so each number is
the mean radiance over a small square of surface:

  slab    a box 2w wide and w deep, w = max(20 mean free paths, 10 diffusion
          lengths 1/σtr), top face at z = 0, seen straight down: Fr(η, 1) +
          the total diffuse reflectance of a beam along the normal
          (reciprocity). Much larger boxes (2000 mean free paths, ~2.6 m for
          skin1) come out 3–6% brighter in Mitsuba's float geometry;
          w = 20 and 100 mean free paths agree;
  sphere  sphere.obj (written here, flat facets, loaded by the C++ test too)
          seen along −z at offsets 0, 0.5 and 0.8 of its radius.

Writes tests/validation/mitsuba_reference.csv: one row per window with the
mean RGB and its standard error over independent batches. Usage:
  python3 tests/validation/mitsuba_reference.py [--spp N] [--batches B]
"""
import argparse
import math
import os
import sys

import mitsuba as mi

HERE = os.path.dirname(os.path.abspath(__file__))

# docs/design.md §2's table (σs', σa in 1/mm, η).
MATERIALS = {
    "skin1": ((0.74, 0.88, 1.01), (0.032, 0.17, 0.48), 1.3),
    "marble": ((2.19, 2.62, 3.00), (0.0021, 0.0041, 0.0071), 1.5),
}
SPHERE_RADIUS = 2.0  # mm
SPHERE_OFFSETS = (0.0, 0.5, 0.8)  # of the radius


def write_sphere_obj(path, radius, rings=48, segments=96):
    """A UV sphere with poles on ±y, outward winding, no normals (flat facets)."""
    verts = [(0.0, radius, 0.0)]
    for i in range(1, rings):
        th = math.pi * i / rings
        for j in range(segments):
            ph = 2 * math.pi * j / segments
            verts.append((radius * math.sin(th) * math.cos(ph), radius * math.cos(th),
                          radius * math.sin(th) * math.sin(ph)))
    verts.append((0.0, -radius, 0.0))
    south = len(verts)  # 1-based index of the south pole
    faces = []

    def ring(i, j):  # 1-based vertex index of ring i (1..rings-1), segment j
        return 2 + (i - 1) * segments + (j % segments)

    for j in range(segments):
        faces.append((1, ring(1, j + 1), ring(1, j)))
        faces.append((south, ring(rings - 1, j), ring(rings - 1, j + 1)))
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)
            faces.append((a, b, c))
            faces.append((a, c, d))
    with open(path, "w") as f:
        f.write("# UV sphere, radius %g mm, written by mitsuba_reference.py\n" % radius)
        for v in verts:
            f.write("v %.9g %.9g %.9g\n" % v)
        for t in faces:
            f.write("f %d %d %d\n" % t)


def medium(sigma_s, sigma_a):
    sigma_t = [s + a for s, a in zip(sigma_s, sigma_a)]
    top = max(sigma_t)  # Mitsuba's RGB values must lie in [0, 1]: σt = scale · rgb
    return {
        "type": "homogeneous",
        "albedo": {"type": "rgb", "value": [s / t for s, t in zip(sigma_s, sigma_t)]},
        "sigma_t": {"type": "rgb", "value": [t / top for t in sigma_t]},
        "scale": top,
        "phase": {"type": "isotropic"},
    }


def render_window(shape, centre, half, spp, seed):
    T = mi.ScalarTransform4f
    sensor = {
        "type": "orthographic",
        "to_world": T().look_at(origin=[centre[0], centre[1], 50.0],
                                target=[centre[0], centre[1], 0.0], up=[0, 1, 0])
        @ T().scale([half, half, 1.0]),
        "film": {"type": "hdrfilm", "width": 1, "height": 1, "rfilter": {"type": "box"},
                 "pixel_format": "rgb"},
        "sampler": {"type": "independent", "sample_count": spp, "seed": seed},
    }
    scene = mi.load_dict({
        "type": "scene",
        "integrator": {"type": "volpath", "max_depth": -1, "rr_depth": 100000},
        "sensor": sensor,
        "sky": {"type": "constant", "radiance": {"type": "rgb", "value": 1.0}},
        "object": shape,
    })
    img = mi.render(scene, seed=seed)
    px = img.array  # 1×1 pixel: the flat RGB values
    return [float(px[c]) for c in range(3)]


def batched(shape, centre, half, spp, batches):
    values = [render_window(shape, centre, half, spp // batches, seed) for seed in range(batches)]
    mean = [sum(v[c] for v in values) / batches for c in range(3)]
    err = [math.sqrt(sum((v[c] - mean[c]) ** 2 for v in values) / (batches - 1) / batches)
           for c in range(3)]
    return mean, err


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--spp", type=int, default=400000)
    ap.add_argument("--batches", type=int, default=8)
    args = ap.parse_args()
    mi.set_variant("scalar_rgb")
    obj = os.path.join(HERE, "sphere.obj")
    write_sphere_obj(obj, SPHERE_RADIUS)
    rows = []
    for name, (ss, sa, eta) in MATERIALS.items():
        bsdf = {"type": "dielectric", "int_ior": eta, "ext_ior": 1.0}
        mfp = 1.0 / min(s + a for s, a in zip(ss, sa))
        sigma_tr = min(math.sqrt(3 * a * (s + a)) for s, a in zip(ss, sa))
        w = max(20 * mfp, 10 / sigma_tr)
        T = mi.ScalarTransform4f
        slab = {"type": "cube", "bsdf": bsdf, "interior": medium(ss, sa),
                "to_world": T().translate([0, 0, -w]) @ T().scale([w, w, w])}
        mean, err = batched(slab, (0.0, 0.0), 0.01, args.spp, args.batches)
        rows.append(("slab", name, 0.0, 0.01, mean, err))
        print("slab", name, mean, err, file=sys.stderr)
        sphere = {"type": "obj", "filename": obj, "face_normals": True, "bsdf": bsdf,
                  "interior": medium(ss, sa)}
        for off in SPHERE_OFFSETS:
            half = 0.02 * SPHERE_RADIUS
            mean, err = batched(sphere, (off * SPHERE_RADIUS, 0.0), half, args.spp, args.batches)
            rows.append(("sphere", name, off * SPHERE_RADIUS, half, mean, err))
            print("sphere", name, off, mean, err, file=sys.stderr)
    with open(os.path.join(HERE, "mitsuba_reference.csv"), "w") as f:
        f.write("# Mitsuba %s volpath, scalar_rgb, %d spp in %d batches; "
                "written by mitsuba_reference.py\n" % (mi.__version__, args.spp, args.batches))
        f.write("scene,material,x_mm,half_mm,r,g,b,err_r,err_g,err_b\n")
        for scene, name, x, half, mean, err in rows:
            f.write("%s,%s,%g,%g,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n" % ((scene, name, x, half) + tuple(mean) + tuple(err)))


if __name__ == "__main__":
    main()
