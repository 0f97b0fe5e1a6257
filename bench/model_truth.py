#!/usr/bin/env python3
"""The subsurface models against the volumetric truth (issue 36): pooled rel. RMSE
sqrt(sum (model - truth)^2 / sum truth^2) over covered pixels, radiance without
the specular lobe, for the thesis' model, the old default and the new default.

Usage:
  bench/model_truth.py truth TSIS [SPP]       volumetric references into
                                              bench/results/truth/<scene>_{a,b}.exr
                                              (two seeds, SPP paths a pixel each, default 256)
  bench/model_truth.py table TSIS [SCENE...]  the table -> bench/results/model_truth.md
                                              (named scenes only: printed, the file kept)

Each reference is the mean of two renders with different seeds; its noise,
sqrt(sum sigma^2 / sum truth^2), is estimated from their difference
(|a - b| / 2 per pixel is the mean's standard error) and subtracted in
quadrature from each model's error ("noise-subtracted"). The two truth spheres
of tests/validation use their light-traced references and stderr images instead.
EXRs are read with oiiotool. Images are 64 x 64 with --aa 1.
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "bench", "results", "truth")
SIZE = 64
COMMON = ["--width", str(SIZE), "--height", str(SIZE), "--no-specular", "--aa", "1"]


def slab_obj(path):
    """A 20 x 20 x 2 mm slab (the thin part, back-lit), one normal per face."""
    if os.path.exists(path):
        return path
    x, y, z = 10.0, 10.0, 1.0
    v = [(-x, -y, -z), (x, -y, -z), (x, y, -z), (-x, y, -z),
         (-x, -y, z), (x, -y, z), (x, y, z), (-x, y, z)]
    faces = [(1, 4, 3, 2), (5, 6, 7, 8), (1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8)]
    with open(path, "w") as f:
        for p in v:
            f.write("v %g %g %g\n" % p)
        for a, b, c, d in faces:
            f.write("f %d %d %d\nf %d %d %d\n" % (a, b, c, a, c, d))
    return path


def two_objects(dir_):
    obj = os.path.join(dir_, "two_objects.obj")
    if not os.path.exists(obj):
        subprocess.run([sys.executable, os.path.join(ROOT, "data/scenes/make_textured_scene.py"),
                        dir_], check=True, capture_output=True)
    return obj


def scenes():
    os.makedirs(OUT, exist_ok=True)
    slab = slab_obj(os.path.join(OUT, "slab_2mm.obj"))
    two = two_objects(os.path.join(OUT, "two_objects"))
    # (name, args, diffusion lengths across the object >= 3: the 15 % target applies)
    return [
        ("sphere_marble_10mm", ["--mesh", "builtin:sphere", "--material", "marble",
                                "--size-mm", "10"], False),
        ("sphere_skin1_30mm", ["--mesh", "builtin:sphere", "--material", "skin1",
                               "--size-mm", "30"], True),
        ("default_marble_10mm", ["--mesh", "builtin:default", "--material", "marble",
                                 "--size-mm", "10"], False),
        ("default_skin1_10mm", ["--mesh", "builtin:default", "--material", "skin1",
                                "--size-mm", "10"], True),
        ("cow_marble_10mm", ["--mesh", "cow", "--material", "marble", "--size-mm", "10"], False),
        ("bunny00_skin1_30mm", ["--mesh", "bunny00", "--material", "skin1", "--size-mm", "30"],
         True),
        ("slab_skin1_2mm_backlit", ["--mesh", slab, "--material", "skin1", "--size-mm",
                                    "28.4", "--eye", "0,0,40", "--light",
                                    "point:6,8,-30:900,900,900"], False),
        ("two_objects_40mm", ["--mesh", two, "--size-mm", "40", "--eye", "0,26,42",
                              "--light", "dir:0.5,-1,0.35:1,1,1",
                              "--light", "dir:-0.6,-0.3,-1:0.4,0.4,0.4",
                              "--mfp", "2,1.2,0.8"], True),
        ("sphere_marble_10mm_sky", ["--mesh", "builtin:sphere", "--material", "marble",
                                    "--size-mm", "10", "--env",
                                    os.path.join(ROOT, "data/env/sky.hdr")], False),
    ]


VALIDATION = {
    "sphere_marble_10mm": "tests/validation/truth_marble_sphere_10mm",
    "sphere_skin1_30mm": "tests/validation/truth_skin1_sphere_30mm",
}

MODELS = [
    ("the thesis' model = the old default (`--model thesis`)", ["--model", "thesis"]),
    ("the new default (`--transport object`)", []),
    ("the new default + `--single-scatter`", ["--single-scatter"]),
]


def pixels(exr):
    out = subprocess.run(["oiiotool", "--info", "-v", "--dumpdata", exr], check=True,
                         capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        m = re.match(r"\s*Pixel \((\d+), (\d+)\):\s*(.*)", line)
        if m:
            rows.append([float(v) for v in m.group(3).split()])
    return rows


def render(tsis, args, aov, extra):
    subprocess.run([tsis, "render"] + args + COMMON + extra + ["--aov", aov, "-o",
                   os.path.join(aov, "image.png"), "--stats", os.path.join(aov, "stats.json")],
                   check=True, capture_output=True)


def truth(tsis, spp):
    for name, args, _ in scenes():
        if name in VALIDATION:
            continue
        for seed, tag in ((11, "a"), (12, "b")):
            exr = os.path.join(OUT, "%s_%s.exr" % (name, tag))
            if os.path.exists(exr):
                continue
            with tempfile.TemporaryDirectory() as aov:
                render(tsis, args, aov, ["--method", "volumetric", "--spp", str(spp),
                                         "--seed", str(seed)])
                subprocess.run(["oiiotool", os.path.join(aov, "radiance.exr"), "--ch", "R,G,B",
                                "-o", exr], check=True)
                if tag == "a":
                    subprocess.run(["oiiotool", os.path.join(aov, "coverage.exr"), "-o",
                                    os.path.join(OUT, name + "_coverage.exr")], check=True)
            print("wrote", exr, flush=True)


def reference(name):
    """(truth rgb rows, per-pixel standard error rows) of a scene."""
    if name in VALIDATION:
        base = os.path.join(ROOT, VALIDATION[name])
        return pixels(base + ".exr"), pixels(base + "_stderr.exr")
    a = pixels(os.path.join(OUT, name + "_a.exr"))
    b = pixels(os.path.join(OUT, name + "_b.exr"))
    mean = [[(x + y) / 2 for x, y in zip(p, q)] for p, q in zip(a, b)]
    err = [[abs(x - y) / 2 for x, y in zip(p, q)] for p, q in zip(a, b)]
    return mean, err


def errors(got, ref, err, cov):
    num = den = noise = 0.0
    for g, r, e, c in zip(got, ref, err, cov):
        if c[0] <= 0.5:
            continue
        for k in range(3):
            num += (g[k] - r[k]) ** 2
            den += r[k] ** 2
            noise += e[k] ** 2
    rel, n = math.sqrt(num / den), math.sqrt(noise / den)
    return rel, n, math.sqrt(max(0.0, rel * rel - n * n))


def table(tsis, only):
    rows = []
    for name, args, thick in scenes():
        if only and name not in only:
            continue
        ref, err = reference(name)
        cells = []
        for label, extra in MODELS:
            with tempfile.TemporaryDirectory() as aov:
                render(tsis, args, aov, extra)
                got = pixels(os.path.join(aov, "radiance.exr"))
                cov = pixels(os.path.join(aov, "coverage.exr"))
            rel, noise, sub = errors(got, ref, err, cov)
            cells.append((rel, sub))
        rows.append((name, thick, noise, cells))
        print(name, ["%.1f / %.1f" % (100 * a, 100 * b) for a, b in cells],
              "noise %.1f" % (100 * noise), flush=True)
    md = ["# The subsurface models against volumetric truth", "",
          "Made by `bench/model_truth.py table build/tsis` (references: `bench/model_truth.py "
          "truth build/tsis 256`, bench/results/truth/, two seeds each; the two spheres: "
          "tests/validation's light-traced truth). Pooled rel. RMSE sqrt(sum (model - truth)^2 / sum truth^2) over "
          "covered pixels, radiance without the specular lobe, %d x %d, `--aa 1`; each cell "
          "measured / with the reference's own noise subtracted in quadrature. Target (issue 36): "
          "<= 15 %% where the object is >= 3 diffusion lengths across (marked *), <= 25 %% "
          "everywhere." % (SIZE, SIZE), "",
          "| scene | reference noise | " + " | ".join(m for m, _ in MODELS) + " |",
          "|---|---|" + "---|" * len(MODELS)]
    for name, thick, noise, cells in rows:
        md.append("| %s%s | %.1f %% | " % (name, " *" if thick else "", 100 * noise) +
                  " | ".join("%.1f / %.1f %%" % (100 * a, 100 * b) for a, b in cells) + " |")
    if only:
        return
    path = os.path.join(ROOT, "bench", "results", "model_truth.md")
    # The notes below the table (what changed when) stay.
    notes = ""
    if os.path.exists(path):
        lines = open(path).read().split("\n")
        rows = [i for i, line in enumerate(lines) if line.startswith("|")]
        if rows:
            notes = "\n".join(lines[rows[-1] + 1:]).rstrip("\n")
    with open(path, "w") as f:
        f.write("\n".join(md) + "\n" + (notes + "\n" if notes.strip() else ""))
    print("wrote", path)


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("truth", "table"):
        sys.exit(__doc__)
    tsis = sys.argv[2]
    if sys.argv[1] == "truth":
        truth(tsis, int(sys.argv[3]) if len(sys.argv) > 3 else 256)
    else:
        table(tsis, sys.argv[3:])


if __name__ == "__main__":
    main()
