#!/usr/bin/env python3
"""Where a texture-space model's error against the volumetric truth lives, by exit angle (issue 24 item 5).

Usage: bench/grazing_error.py TSIS [METHOD [ARGS...]]   (default method: pyramid)
ARGS go to `tsis render` after the truth's own (e.g. --no-specular --aa 1
--single-scatter: the truth has no GGX lobe).

For the two truth scenes of tests/validation (truth.json: their `tsis render`
arguments; truth_*.exr: the light tracer's radiance to <= 1 % noise), renders
METHOD with the same arguments, and bins every covered pixel by the cosine of
its exit angle, cos(theta_o) = n . (eye - x) / |eye - x| (normal and position
AOVs; the eye from --stats' scene_args), and again by the cosine of the light's
incidence, cos(theta_i) = n . l (negative: the side turned away, the light
reaching it through the object). Per bin: the share of the pixels, the share
of the squared error (all channels), the same after one least-squares scale
per channel (what is left once the level is right: the shape), and the ratio
model / truth (red); over all pixels the relative RMSE (RMSE / the truth's
mean, as `tsis compare`) and per channel the ratio model / truth in the
shadow-line band -0.2 < cos(theta_i) < 0.2. EXRs are read with oiiotool.
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BINS = [0.0, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0001]
LIGHT_BINS = [-1.0001, -0.5, -0.2, 0.0, 0.2, 0.5, 1.0001]


def pixels(exr):
    out = subprocess.run(["oiiotool", "--info", "-v", "--dumpdata", exr], check=True,
                         capture_output=True, text=True).stdout
    return {(int(m[1]), int(m[2])): [float(v) for v in m[3].split()]
            for m in re.finditer(r"Pixel \((\d+), (\d+)\): ([-\d.e ]+)", out)}


def main():
    tsis = sys.argv[1]
    method = sys.argv[2] if len(sys.argv) > 2 else "pyramid"
    extra = sys.argv[3:]
    truth = json.load(open(os.path.join(ROOT, "tests/validation/truth.json")))
    tmp = tempfile.mkdtemp(prefix="grazing_")
    for name, entry in truth.items():
        aov = os.path.join(tmp, name)
        stats = aov + ".json"
        subprocess.run([tsis, "render", *entry["args"], "--method", method, *extra, "--aov", aov,
                        "--stats", stats, "-o", aov + ".png"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        args = json.load(open(stats))["scene_args"]
        eye = [float(v) for v in args[args.index("--eye") + 1].split(",")]
        ref = pixels(os.path.join(ROOT, "tests/validation", name + ".exr"))
        got = pixels(aov + "/radiance.exr")
        pos, nrm = pixels(aov + "/position.exr"), pixels(aov + "/normal.exr")
        cov = pixels(aov + "/coverage.exr")
        light = next(a for a in args[args.index("--light") + 1:] if a.startswith("point:"))
        lp = [float(v) for v in light.split(":")[1].split(",")]
        samples = []  # (cos θo, cos θi, model rgb, truth rgb)
        for xy, c in cov.items():
            if c[0] <= 0 or xy not in ref:
                continue
            x, n = pos[xy], nrm[xy]
            v = [eye[i] - x[i] for i in range(3)]
            l = [lp[i] - x[i] for i in range(3)]
            cos_o = sum(n[i] * v[i] for i in range(3)) / math.sqrt(sum(t * t for t in v))
            cos_i = sum(n[i] * l[i] for i in range(3)) / math.sqrt(sum(t * t for t in l))
            samples.append((cos_o, cos_i, got.get(xy, [0.0, 0.0, 0.0]), ref[xy]))
        sq = sum((m[i] - t[i]) ** 2 for _, _, m, t in samples for i in range(3))
        mean = sum(sum(t) for _, _, _, t in samples) / (3 * len(samples))
        band = [smp for smp in samples if -0.2 < smp[1] < 0.2]
        ratio = [sum(m[i] for _, _, m, _ in band) / max(sum(t[i] for _, _, _, t in band), 1e-300)
                 for i in range(3)]
        # One scale per channel, least squares: the level taken out.
        scale = [sum(m[i] * t[i] for _, _, m, t in samples) /
                 max(sum(m[i] ** 2 for _, _, m, _ in samples), 1e-300) for i in range(3)]
        shaped = sum((scale[i] * m[i] - t[i]) ** 2 for _, _, m, t in samples for i in range(3))
        print("\n%s, %s %s: relative RMSE %.1f %% (%.1f %% after the scale); model / truth at "
              "-0.2 < cos θi < 0.2: %.3f %.3f %.3f" % (
                  name, method, " ".join(extra), 100 * math.sqrt(sq / (3 * len(samples))) / mean,
                  100 * math.sqrt(shaped / (3 * len(samples))) / mean, *ratio))
        for title, key, bins in (("exit cos θo", 0, BINS), ("light cos θi", 1, LIGHT_BINS)):
            rows = [[0, 0.0, 0.0, 0.0, 0.0] for _ in bins[:-1]]
            for smp in samples:
                m, t = smp[2], smp[3]
                b = next(k for k in range(len(bins) - 1) if smp[key] < bins[k + 1])
                rows[b][0] += 1
                rows[b][1] += sum((m[i] - t[i]) ** 2 for i in range(3))
                rows[b][2] += sum((scale[i] * m[i] - t[i]) ** 2 for i in range(3))
                rows[b][3] += m[0]
                rows[b][4] += t[0]
            px, sq, shape = (sum(r[k] for r in rows) for k in (0, 1, 2))
            print("\n%s, %s against the truth, by %s (scale %.2f %.2f %.2f):\n" % (
                name, method, title, *scale))
            print("| %s | pixels | squared error | after one scale | %s / truth (red) |" % (
                title, method))
            print("|---|---|---|---|---|")
            for k, r in enumerate(rows):
                if r[0] == 0:
                    continue
                print("| %.1f to %.1f | %.1f %% | %.1f %% | %.1f %% | %.2f |" % (
                    bins[k], min(bins[k + 1], 1.0), 100 * r[0] / px, 100 * r[1] / sq,
                    100 * r[2] / shape, r[3] / r[4] if r[4] > 0 else float("nan")))


if __name__ == "__main__":
    main()
