#!/usr/bin/env python3
"""Per-stage A/B of tsis binaries, interleaved in one run (the machine is
shared and noisy: every round runs each binary once, in turn; medians).

  bench/stage_ab.py [--rounds R] [--frames F] NAME=TSIS ... -- RENDER ARGS

Each run is `TSIS render --frames F --stats …  RENDER ARGS`; a stage's time
is the last frame's (the ones before warm the caches; with
--no-reuse-lighting that frame redraws the light views and the flux atlas as
a frame whose light moved does). Prints a markdown table: median (min–max) ms
per stage and binary, of the wall time (`ms`) and then of the process' CPU
time over each stage (`cpu_ms`, all threads: less moved by other jobs on a
shared machine than the wall time). With --animate, each run is `TSIS animate --frames F
ARGS` instead and only the frames' render ms after the first are compared.
"""
import json
import statistics
import subprocess
import sys
import tempfile


def main(argv):
    rounds, frames, animate = 5, 6, False
    while argv and argv[0].startswith("--"):
        flag = argv.pop(0)
        if flag == "--rounds":
            rounds = int(argv.pop(0))
        elif flag == "--frames":
            frames = int(argv.pop(0))
        elif flag == "--animate":
            animate = True
    split = argv.index("--")
    bins = [a.split("=", 1) for a in argv[:split]]
    args = argv[split + 1:]
    ms = {name: {} for name, _ in bins}
    cpu = {name: {} for name, _ in bins}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(rounds):
            for name, tsis in bins:
                stats = f"{tmp}/{name}.json"
                if animate:
                    cmd = [tsis, "animate", "--frames", str(frames), "-o", f"{tmp}/{name}",
                           "--stats", stats] + args
                else:
                    cmd = [tsis, "render", "--frames", str(frames), "-o", f"{tmp}/{name}.png",
                           "--stats", stats] + args
                subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
                j = json.load(open(stats))
                if animate:
                    for f in j["per_frame"][1:]:
                        ms[name].setdefault("render (steady frames)", []).append(f["render_ms"])
                else:
                    for stage, v in j["ms"].items():
                        ms[name].setdefault(stage, []).append(v)
                    for stage, v in j.get("cpu_ms", {}).items():
                        cpu[name].setdefault(stage, []).append(v)
    table(bins, ms, "ms")
    if any(cpu[name] for name, _ in bins):
        print()
        table(bins, cpu, "CPU ms")


def table(bins, ms, unit):
    stages = []
    for name, _ in bins:
        stages += [s for s in ms[name] if s not in stages]
    print("| stage | " + " | ".join(f"{n} {unit}" for n, _ in bins) + " |")
    print("|---" * (len(bins) + 1) + "|")
    for s in stages:
        cells = []
        for name, _ in bins:
            v = ms[name].get(s)
            cells.append(f"{statistics.median(v):.1f} ({min(v):.1f}–{max(v):.1f})" if v else "—")
        print(f"| {s} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
