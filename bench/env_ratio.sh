#!/usr/bin/env bash
# The environment at the price of a light (issue 38): the frame with the map
# turning against the frame with the lights moving, for one or more tsis
# binaries, interleaved in one run (the machine is shared: every round runs
# each case once, in turn; medians).
#
#   bench/env_ratio.sh [--rounds R] NAME=TSIS ...
#
# Each case is `tsis animate --orbit --frames 16` (every light, and the map
# with --env, turns one step a frame) with the default scene's two lights
# written out, alone ("lights") or with --env data/env/sky.hdr ("env": its
# sun and its residual besides), on the default scene and cow; a case's
# figure is the median render ms of the frames after the first. Writes
# bench/results/env_ratio.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
rounds=3
if [ "${1:-}" = --rounds ]; then
    rounds=$2
    shift 2
fi
[ $# -ge 1 ] || { echo "usage: $0 [--rounds R] NAME=TSIS ..." >&2; exit 2; }
out=$root/bench/results/env_ratio.md
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
lights="--light point:-5.85,9.75,-13:298.3,298.3,298.3 --light dir:0.6,-0.4,-1:0.12,0.12,0.12"
meshes="builtin:default $root/data/meshes/cow.off"
load=$(cut -d' ' -f1-3 /proc/loadavg)
for r in $(seq "$rounds"); do
    [ -t 2 ] && printf 'round %s of %s\r' "$r" "$rounds" >&2
    for mesh in $meshes; do
        for named in "$@"; do
            name=${named%%=*} bin=${named#*=}
            for case in lights env; do
                env=""
                [ $case = env ] && env="--env $root/data/env/sky.hdr"
                # shellcheck disable=SC2086
                "$bin" animate --mesh "$mesh" -o "$tmp/frames" --frames 16 --orbit $lights $env \
                    --stats "$tmp/stats.json" >/dev/null 2>"$tmp/err" ||
                    { echo "$name $mesh $case failed: $(cat "$tmp/err")" >&2; exit 1; }
                python3 -c "import json,statistics,sys; f=json.load(open(sys.argv[1]))['per_frame'][1:]; print('%.1f' % statistics.median(x['render_ms'] for x in f))" \
                    "$tmp/stats.json" | sed "s|^|$name ${mesh##*/} $case |" >>"$tmp/rows"
            done
        done
    done
done
[ -t 2 ] && printf '%*s\r' 20 '' >&2
python3 - "$tmp/rows" "$rounds" "$load" "$(cut -d' ' -f1-3 /proc/loadavg)" "$@" >"$out" <<'EOF'
import collections
import statistics
import sys
import time

rows, rounds, load_start, load_end = sys.argv[1:5]
names = [a.split("=", 1)[0] for a in sys.argv[5:]]
ms = collections.defaultdict(list)
for line in open(rows):
    name, mesh, case, v = line.split()
    ms[(name, mesh, case)].append(float(v))
meshes = list(dict.fromkeys(m for _, m, _ in ms))
print("# The environment at the price of a light\n")
print(f"Made by `bench/env_ratio.sh --rounds {rounds}` on {time.strftime('%Y-%m-%dT%H:%MZ', time.gmtime())}"
      f" ({', '.join(names)}); load average {load_start} at the start, {load_end} at the end.")
print("512², the default method; `tsis animate --orbit --frames 16`: every light (and the map) turns"
      " one step a frame; the median render ms of the frames after the first, then the median over"
      " the rounds (each round runs every case in turn). *lights*: the default scene's two lights;"
      " *env*: the same with `--env data/env/sky.hdr` (its sun a third light, its residual per"
      " atlas texel). Issue 38 asks env / lights ≤ 1.3.\n")
print("| mesh | binary | lights ms (rounds) | env ms (rounds) | env / lights |")
print("|---|---|---|---|---|")
for mesh in meshes:
    for name in names:
        li, en = ms[(name, mesh, "lights")], ms[(name, mesh, "env")]
        print(f"| {mesh} | {name} | {statistics.median(li):.1f} ({', '.join(map(str, li))}) |"
              f" {statistics.median(en):.1f} ({', '.join(map(str, en))}) |"
              f" {statistics.median(en) / statistics.median(li):.2f} |")
EOF
cat "$out"
