"""Throughput of tsis.distributed.sweep against one Renderer in one process:
16 frames (4 materials × 4 sizes of builtin:sphere, 128×128, the default
method) rendered (a) one after another by one Renderer here, (b) by
sweep(backend="local", workers=2), (c) by sweep(backend="ray", workers=2) on a
local Ray (ray.init(num_cpus=2)); a, b, c in turn, ROUNDS times.

(a) times the 16 frames after one warm-up frame (its own number). (b) and (c)
are the sweep's wall time, its workers' start (process, Renderer) included;
the first job of each worker (its first frame: kernels built, atlases made)
is given on its own from the index. Writes bench/results/sweep_throughput.md.

Usage (from the repository root):
  PYTHONPATH=build/python build/pyenv/bin/python bench/sweep_throughput.py [ROUNDS]
"""
import json
import os
import subprocess
import sys
import tempfile
import time

import tsis
from tsis import distributed

ROUNDS = int(sys.argv[1]) if len(sys.argv) > 1 else 2
MATERIALS = ["skin1", "marble", "ketchup", "wholemilk"]
SIZES = [5, 10, 20, 40]  # --size-mm
RENDER = dict(width=128, height=128)
JOBS = distributed.grid(scene=dict(mesh="builtin:sphere", material=MATERIALS, size_mm=SIZES),
                        render=RENDER)
TTY = sys.stdout.isatty()


def progress(text):
    if TTY:
        print(f"\r{text:<70}", end="", flush=True)


def serial():
    renderer = tsis.Renderer()
    t = time.perf_counter()
    renderer.render(tsis.Scene(**JOBS[0]["scene"]), **RENDER)  # warm-up
    first = time.perf_counter() - t
    t = time.perf_counter()
    for job in JOBS:
        renderer.render(tsis.Scene(**job["scene"]), **job["render"])
    return {"wall": time.perf_counter() - t, "first": [first]}


def swept(backend):
    with tempfile.TemporaryDirectory() as out:
        t = time.perf_counter()
        summary = distributed.sweep(JOBS, out, workers=2, backend=backend)
        wall = time.perf_counter() - t
        assert summary["ok"] == len(JOBS), summary
        with open(os.path.join(out, "index.jsonl")) as f:
            lines = [json.loads(line) for line in f]
    first, seen = [], set()
    for e in lines:  # in the order they finished: a worker's first line is its first job
        if e["worker"] not in seen:
            seen.add(e["worker"])
            first.append(e["seconds"])
    return {"wall": wall, "first": first}


def main():
    import ray
    load = os.getloadavg()
    model = next((line.split(":", 1)[1].strip() for line in
                  subprocess.run(["lscpu"], capture_output=True, text=True).stdout.splitlines()
                  if line.startswith("Model name")), "?")
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    results = {"a": [], "b": [], "c": []}
    try:
        for r in range(ROUNDS):
            for key, run in (("a", serial), ("b", lambda: swept("local")),
                             ("c", lambda: swept("ray"))):
                progress(f"round {r + 1}/{ROUNDS}: {key}")
                results[key].append(run())
    finally:
        ray.shutdown()
    progress("")
    if TTY:
        print("\r", end="")
    n = len(JOBS)
    names = {"a": "(a) serial, one Renderer (warm)",
             "b": "(b) sweep local, 2 workers",
             "c": "(c) sweep ray, 2 workers"}
    rows = []
    for r in range(ROUNDS):
        a = results["a"][r]["wall"]
        for key in "abc":
            x = results[key][r]
            ratio = "1" if key == "a" else f"{x['wall'] / a:.2f}"
            rows.append(f"| {r + 1} | {names[key]} | {x['wall']:.2f} | {n / x['wall']:.1f} | "
                        f"{ratio} | {', '.join(f'{s:.2f}' for s in x['first'])} |")
    text = f"""# sweep throughput

Command (from the repository root, {time.strftime('%Y-%m-%d')}):
`PYTHONPATH=build/python build/pyenv/bin/python bench/sweep_throughput.py {ROUNDS}`

Machine: {model}, {os.cpu_count()} cores (shared with other work), OpenCL as
the build found it; Ray {ray.__version__}. Load average at start:
{load[0]:.2f} {load[1]:.2f} {load[2]:.2f}.

{n} frames: {len(MATERIALS)} materials ({', '.join(MATERIALS)}) × {len(SIZES)} sizes
(--size-mm {', '.join(map(str, SIZES))}) of builtin:sphere, 128×128, the default method.
(a) after one warm-up frame; (b), (c) the sweep's wall time, its 2 workers'
start included. "first frames": the warm-up frame of (a), and the first job
of each worker (from index.jsonl), in seconds.

| round | run | wall s | renders/s | ratio to (a) | first frames s |
|---|---|---|---|---|---|
""" + "\n".join(rows) + "\n"
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results",
                        "sweep_throughput.md")
    with open(path, "w") as f:
        f.write(text)
    print("\n".join(rows))
    print(f"wrote {os.path.relpath(path)}")


if __name__ == "__main__":
    main()
