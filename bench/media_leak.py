#!/usr/bin/env python3
"""Light crossing between separate solids (issue 20 item 1), through a tsis binary.

Usage: bench/media_leak.py TSIS [METHOD...]
       bench/media_leak.py TSIS --side[=ROWS] [--light-res=R] [METHOD...]
(issue 39: solids side by side; ROWS: only the configurations whose name
holds it; R: the shadow maps' resolution, default tsis' own)

Two skim-milk cubes 0.5 mm apart (a 20 mm cube over a 16 mm one, 49.4 mm
scene), a directional light from above, so the lower cube lies wholly in the
upper one's shadow; the camera looks at their front faces. Per method (all ten
by default) it prints the mean red radiosity of the upper cube's front face in
its top millimetre (lit) and in the millimetre above the gap, and of the lower
cube's front face in the millimetre below the gap: any light there crossed the
gap. Pixels are told apart by their position AOV; the EXRs are read with
oiiotool. The same scene as tests/media_test.cpp.
"""
import collections
import math
import os
import re
import subprocess
import sys
import tempfile

METHODS = ["pyramid", "tsis", "hybrid", "ltsm", "mis", "hierarchical", "reference", "tsm", "lss",
           "volumetric"]


def box(lo, hi):
    """Quads (normal, four corners counter-clockwise from outside) of a box."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    return [((1, 0, 0), [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)]),
            ((-1, 0, 0), [(x0, y0, z1), (x0, y1, z1), (x0, y1, z0), (x0, y0, z0)]),
            ((0, 1, 0), [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)]),
            ((0, -1, 0), [(x0, y0, z1), (x0, y0, z0), (x1, y0, z0), (x1, y0, z1)]),
            ((0, 0, 1), [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]),
            ((0, 0, -1), [(x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0)])]


def write_obj(path):
    quads = box((-10, 0.25, -10), (10, 20.25, 10)) + box((-8, -20.25, -8), (8, -0.25, 8))
    with open(path, "w") as f:
        for _, corners in quads:
            for p in corners:
                f.write("v %g %g %g\n" % p)
        for n, _ in quads:
            f.write("vn %g %g %g\n" % n)
        for k in range(len(quads)):
            a, b, c, d = (4 * k + i for i in range(1, 5))
            for tri in ((a, b, c), (a, c, d)):
                f.write("f " + " ".join("%d//%d" % (v, k + 1) for v in tri) + "\n")


def pixels(exr):
    out = subprocess.run(["oiiotool", "--info", "-v", "--dumpdata", exr], check=True,
                         capture_output=True, text=True).stdout
    return {(int(m[1]), int(m[2])): tuple(float(v) for v in m[3].split())
            for m in re.finditer(r"Pixel \((\d+), (\d+)\): ([-\d.e ]+)", out)}


# --- Side by side (issue 39 item 1) -------------------------------------------
# A lit solid A (a unit cube or a unit-diameter sphere at the origin) and a
# solid B beside it across a gap (a fraction of A's size) along `axis`; the
# light travels along the axis (tilted by `tilt`), so that A's shadow holds B
# whole. The camera looks down; the figure is the mean radiosity of B's top
# over A's top (the truth: 0).
SIDE = [  # name, shape, gap, B's half size, axis, light, tilt (down, across)
    ("cubes, gap 0.1 %, dir +x", "cube", 0.001, 0.5, (1, 0, 0), "dir", (0, 0)),
    ("cubes, gap 2 %, dir +x", "cube", 0.02, 0.5, (1, 0, 0), "dir", (0, 0)),
    ("cubes, gap 10 %, dir +x", "cube", 0.10, 0.5, (1, 0, 0), "dir", (0, 0)),
    ("cubes, gap 30 %, dir +x", "cube", 0.30, 0.5, (1, 0, 0), "dir", (0, 0)),
    ("cubes, gap 2 %, dir -x", "cube", 0.02, 0.5, (-1, 0, 0), "dir", (0, 0)),
    ("cubes, gap 30 %, dir -x", "cube", 0.30, 0.5, (-1, 0, 0), "dir", (0, 0)),
    ("cubes, gap 2 %, dir +z", "cube", 0.02, 0.5, (0, 0, 1), "dir", (0, 0)),
    ("cubes, gap 10 %, dir oblique", "cube", 0.10, 0.25, (1, 0, 0), "dir", (0.2, 0.2)),
    ("cubes, gap 10 %, point +x", "cube", 0.10, 0.5, (1, 0, 0), "point", (0, 0)),
    ("cubes, gap 10 %, point -z", "cube", 0.10, 0.5, (0, 0, -1), "point", (0, 0)),
    ("spheres, gap 2 %, dir +x", "sphere", 0.02, 0.4, (1, 0, 0), "dir", (0, 0)),
    ("spheres, gap 10 %, point oblique", "sphere", 0.10, 0.3, (-1, 0, 0), "point", (0.1, 0.1)),
]


def cube_quads(centre, half):
    c = [centre[i] for i in range(3)]
    return box(tuple(c[i] - half for i in range(3)), tuple(c[i] + half for i in range(3)))


def write_side_obj(path, shape, gap, half_b, axis):
    """A at the origin, B at axis · (0.5 + gap + half_b); returns B's centre."""
    cb = tuple(a * (0.5 + gap + half_b) for a in axis)
    with open(path, "w") as f:
        if shape == "cube":
            quads = cube_quads((0, 0, 0), 0.5) + cube_quads(cb, half_b)
            for _, corners in quads:
                for p in corners:
                    f.write("v %.9g %.9g %.9g\n" % p)
            for n, _ in quads:
                f.write("vn %g %g %g\n" % n)
            for k in range(len(quads)):
                a, b, c, d = (4 * k + i for i in range(1, 5))
                for tri in ((a, b, c), (a, c, d)):
                    f.write("f " + " ".join("%d//%d" % (v, k + 1) for v in tri) + "\n")
        else:
            base = 1
            for centre, r in (((0, 0, 0), 0.5), (cb, half_b)):
                rings, segs = 48, 96
                for i in range(rings + 1):
                    t = math.pi * i / rings
                    for j in range(segs):
                        p = 2 * math.pi * j / segs
                        n = (math.sin(t) * math.cos(p), math.cos(t), -math.sin(t) * math.sin(p))
                        f.write("v %.9g %.9g %.9g\n" % tuple(centre[k] + r * n[k] for k in range(3)))
                        f.write("vn %.9g %.9g %.9g\n" % n)
                for i in range(rings):
                    for j in range(segs):
                        a = base + i * segs + j
                        b = base + i * segs + (j + 1) % segs
                        c, d = a + segs, b + segs
                        # No zero-area triangles at the poles.
                        tris = ([(a, c, d)] if i + 1 < rings else []) + ([(a, d, b)] if i else [])
                        for tri in tris:
                            f.write("f " + " ".join("%d//%d" % (v, v) for v in tri) + "\n")
                base += (rings + 1) * segs
    return cb


def side_case(tsis, tmp, method, case, extra=()):
    name, shape, gap, half_b, axis, light, tilt = case
    mesh = os.path.join(tmp, re.sub(r"[^a-z0-9]+", "_", name) + ".obj")
    cb = write_side_obj(mesh, shape, gap, half_b, axis)
    lo = [min(-0.5, cb[i] - half_b) for i in range(3)]
    hi = [max(0.5, cb[i] + half_b) for i in range(3)]
    centre = [(lo[i] + hi[i]) / 2 for i in range(3)]
    scale = 50.0 / math.sqrt(sum((hi[i] - lo[i]) ** 2 for i in range(3)))
    # The light's direction of travel: the axis, tilted down by tilt[0] and
    # across by tilt[1] (across: z, or x when the axis is z).
    across = (0, 0, 1) if axis[2] == 0 else (1, 0, 0)
    d = [axis[i] - tilt[0] * (i == 1) + tilt[1] * across[i] for i in range(3)]
    if light == "dir":
        spec = "dir:%g,%g,%g:1,1,1" % tuple(d)
    else:  # 3 units before A's centre, against the direction of travel
        p = [(-3 * d[i] / math.sqrt(sum(v * v for v in d)) - centre[i]) * scale for i in range(3)]
        i = sum(v * v for v in p)
        spec = "point:%g,%g,%g:%g,%g,%g" % (*p, i, i, i)
    aov = os.path.join(tmp, "side_" + method)
    subprocess.run([tsis, "render", "--mesh", mesh, "--size-mm", "50", "--material", "skimmilk",
                    "--light", spec, "--eye", "0,110,0.01", "--target", "0,0,0", "--up", "0,0,-1",
                    "--fov", "35", "--width", "128", "--height", "128", "--method", method,
                    "--aov", aov, "-o", aov + ".png"] +
                   (["--spp", "4"] if method == "volumetric" else []) + list(extra),
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    pos, nrm = pixels(aov + "/position.exr"), pixels(aov + "/normal.exr")
    rad = pixels(aov + "/radiosity.exr")
    tops = {"A": [], "B": []}
    for xy, p in pos.items():
        if nrm.get(xy, (0, 0, 0))[1] < (0.9 if shape == "cube" else 0.5):
            continue
        u = [p[i] / scale + centre[i] for i in range(3)]
        inside_b = max(abs(u[i] - cb[i]) for i in range(3)) < half_b + 1e-3
        tops["B" if inside_b else "A"].append(sum(rad.get(xy, (0, 0, 0))[:3]))
    mean = {k: sum(v) / len(v) if v else float("nan") for k, v in tops.items()}
    return mean["A"], mean["B"]


def side_main(tsis, methods, only=None, extra=()):
    tmp = tempfile.mkdtemp(prefix="media_leak_side_")
    print("B's top over A's top, % (truth 0); columns: methods\n")
    print("| configuration | " + " | ".join(methods) + " |")
    print("|---|" + "---|" * len(methods))
    for case in SIDE:
        if only and only not in case[0]:
            continue
        row = []
        for method in methods:
            a, b = side_case(tsis, tmp, method, case, extra)
            # lss sees only what the camera sees lit: with A's top dark, B's
            # absolute value (0 where nothing leaks).
            row.append("%.2f" % (100 * b / a) if a > 0 else "A dark, B %.2g" % b)
        print("| %s | %s |" % (case[0], " | ".join(row)), flush=True)


def main():
    tsis = sys.argv[1]
    if sys.argv[2:3] and sys.argv[2].startswith("--side"):
        rest = sys.argv[3:]
        extra = []
        if rest and rest[0].startswith("--light-res="):
            extra = ["--light-res", rest.pop(0).partition("=")[2]]
        side_main(tsis, rest or METHODS, sys.argv[2].partition("=")[2], extra)
        return
    methods = sys.argv[2:] or METHODS
    tmp = tempfile.mkdtemp(prefix="media_leak_")
    mesh = os.path.join(tmp, "two_cubes.obj")
    write_obj(mesh)
    print("| method | upper, lit top mm | upper, above the gap | lower, below the gap | "
          "below / above the gap |")
    print("|---|---|---|---|---|")
    for method in methods:
        aov = os.path.join(tmp, method)
        subprocess.run([tsis, "render", "--mesh", mesh, "--size-mm", "49.3988866",
                        "--material", "skimmilk", "--light", "dir:0,-1,0:1,1,1", "--eye", "0,0,70",
                        "--fov", "40", "--width", "128", "--height", "128", "--method", method,
                        "--aov", aov, "-o", aov + ".png"] +
                       (["--spp", "4"] if method == "volumetric" else []),
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        pos, rad = pixels(aov + "/position.exr"), pixels(aov + "/radiosity.exr")
        sums = collections.defaultdict(list)
        for xy, (x, y, z) in pos.items():
            if z < 7.9 or abs(x) > 7:  # front faces, away from the side edges
                continue
            band = "lit" if y > 19.25 else "above" if 0.25 < y < 1.25 else \
                "below" if -1.25 < y < -0.25 else None
            if band:
                sums[band].append(rad.get(xy, (0.0,))[0])
        mean = {k: sum(v) / len(v) for k, v in sums.items()}
        ratio = mean["below"] / mean["above"] if mean.get("above") else float("nan")
        print("| %s | %.4g | %.4g | %.3g | %.1f %% |" % (method, mean.get("lit", 0),
                                                        mean.get("above", 0),
                                                        mean.get("below", 0), 100 * ratio))


if __name__ == "__main__":
    main()
