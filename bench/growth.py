#!/usr/bin/env python3
"""How a frame grows (issue 38): frame and stage times against the triangle
count (one shape, an icosphere subdivided from 1,280 to 1.3M triangles) and
against the pixel count (cow, 256² to 2048²), with the lights moving and with
the environment map turning, and each stage's fitted exponent (the slope of
log ms against log triangles or log pixels).

  bench/growth.py TSIS [--frames N] [--out bench/results/growth.md]

Each point is `TSIS animate --orbit --frames N` (every light, and the map with
--env, turns a step a frame), the median of the frames after the first; the
first frame (the atlas, the transport fit, the environment's transfer: once
per mesh, cached) is reported apart. A stage under 0.5 ms at the largest
point is left out of the fits (its slope is noise). Progress on a terminal,
quiet otherwise.
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

from noisy_scan import subdivide  # bench/: the script's own folder is on the path

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SKY = os.path.join(ROOT, "data", "env", "sky.hdr")
COW = os.path.join(ROOT, "data", "meshes", "cow.off")


def icosphere(level, path):
    """An icosphere of 20·4^level triangles written as OBJ (unit radius):
    each level splits every triangle in four (noisy_scan.subdivide) and puts
    the new vertices back on the sphere."""
    t = (1 + 5 ** 0.5) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def unit(vs):
        return [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in vs]

    verts = unit(verts)
    for _ in range(level):
        verts, faces = subdivide(verts, faces)
        verts = unit(verts)
    with open(path, "w") as f:
        f.writelines(f"v {x:.7f} {y:.7f} {z:.7f}\n" for x, y, z in verts)
        f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
    return len(faces)


def frame(tsis, tmp, frames, args):
    """(median render ms after the first frame, first frame ms, {stage: median ms})."""
    stats = os.path.join(tmp, "stats.json")
    cmd = [tsis, "animate", "-o", os.path.join(tmp, "frames"), "--frames", str(frames),
           "--orbit", "--stats", stats] + args
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"growth: {' '.join(cmd)} failed: {r.stderr.strip()}")
    per = json.load(open(stats))["per_frame"]
    rest = per[1:]
    stages = {}
    for k in set().union(*(p.get("stage_ms", {}) for p in rest)):
        if k != "total":
            stages[k] = statistics.median(p.get("stage_ms", {}).get(k, 0.0) for p in rest)
    return statistics.median(p["render_ms"] for p in rest), per[0]["render_ms"], stages


def slope(xs, ys):
    """Least-squares slope of log y against log x (None with a y ≤ 0 or
    fewer than two points)."""
    if len(xs) < 2 or any(y <= 0 for y in ys):
        return None
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = statistics.fmean(lx), statistics.fmean(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def table(title, unit, xs, runs, out):
    """Markdown: one row per point (frame ms, first frame ms), then the exponents."""
    out.append(f"## {title}\n")
    out.append(f"| {unit} | lights ms | env ms | first frame ms (lights / env) |")
    out.append("|---|---|---|---|")
    for i, x in enumerate(xs):
        out.append(f"| {x:,} | {runs['lights'][i][0]:.1f} | {runs['env'][i][0]:.1f} |"
                   f" {runs['lights'][i][1]:.0f} / {runs['env'][i][1]:.0f} |")
    out.append("")
    out.append(f"Fitted exponent (ms ∝ {unit}^k) of the frame and of each stage over 0.5 ms at"
               " the largest point:\n")
    out.append("| stage | k, lights | k, env | ms at the largest (lights / env) |")
    out.append("|---|---|---|---|")
    names = ["frame"] + sorted(set(runs["lights"][-1][2]) | set(runs["env"][-1][2]),
                               key=lambda k: -runs["env"][-1][2].get(k, 0))
    for name in names:
        cells = []
        last = []
        for case in ("lights", "env"):
            ys = [r[0] if name == "frame" else r[2].get(name, 0.0) for r in runs[case]]
            last.append(ys[-1])
            k = slope(xs, ys) if ys[-1] >= 0.5 else None
            cells.append("–" if k is None else f"{k:.2f}")
        if name != "frame" and max(last) < 0.5:
            continue
        out.append(f"| {name} | {cells[0]} | {cells[1]} | {last[0]:.1f} / {last[1]:.1f} |")
    out.append("")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("tsis")
    p.add_argument("--frames", type=int, default=8)
    p.add_argument("--levels", default="3,4,5,6,7,8")
    p.add_argument("--sizes", default="256,512,1024,2048")
    p.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "growth.md"))
    a = p.parse_args()
    tty = sys.stderr.isatty()
    load = open("/proc/loadavg").read().split()[:3]
    out = ["# How a frame grows: triangles and pixels\n",
           f"Made by `bench/growth.py` on {time.strftime('%Y-%m-%dT%H:%MZ', time.gmtime())};"
           f" {os.cpu_count()} cores, load average {' '.join(load)} at the start."
           f" `tsis animate --orbit --frames {a.frames}`, the default method; lights: the"
           " default lights; env: `--env data/env/sky.hdr` alone (its sun and its residual: a"
           " map given without --light lights the scene by itself). A cell is the median"
           " render ms of the frames after the first.\n"]
    with tempfile.TemporaryDirectory() as tmp:
        levels = [int(x) for x in a.levels.split(",")]
        tris, runs = [], {"lights": [], "env": []}
        for level in levels:
            mesh = os.path.join(tmp, f"ico{level}.obj")
            tris.append(icosphere(level, mesh))
            for case in ("lights", "env"):
                if tty:
                    print(f"\rtriangles {tris[-1]:,} {case}   ", end="", file=sys.stderr)
                extra = ["--env", SKY] if case == "env" else []
                runs[case].append(frame(a.tsis, tmp, a.frames, ["--mesh", mesh] + extra))
        table("Against triangles (an icosphere, 512², atlas 512²)", "triangles", tris, runs, out)
        sizes = [int(x) for x in a.sizes.split(",")]
        runs = {"lights": [], "env": []}
        for s in sizes:
            for case in ("lights", "env"):
                if tty:
                    print(f"\rpixels {s}² {case}          ", end="", file=sys.stderr)
                extra = ["--env", SKY] if case == "env" else []
                runs[case].append(frame(a.tsis, tmp, a.frames, ["--mesh", COW, "--width", str(s),
                                                                "--height", str(s)] + extra))
        table("Against pixels (cow, atlas 512²)", "pixels", [s * s for s in sizes], runs, out)
    if tty:
        print("\r" + " " * 40 + "\r", end="", file=sys.stderr)
    with open(a.out, "w") as f:
        f.write("\n".join(out))
    print("\n".join(out))


if __name__ == "__main__":
    main()
