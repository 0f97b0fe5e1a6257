#!/usr/bin/env python3
"""Light crossing between separate solids (issue 20 item 1), through a tsis binary.

Usage: bench/media_leak.py TSIS [METHOD...]

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


def main():
    tsis = sys.argv[1]
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
