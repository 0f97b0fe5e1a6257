#!/usr/bin/env bash
# A material the transport was never fitted for, in `tsis view` (issue 36:
# "a σ slider is not interactive"), under a virtual display: a scripted
# session of 5 σa changes (each a new fit) and one orbit step, from an empty
# cache. The window shows each change's frame without the object's transport
# at once and the frame with it when the fit, made in the background, is done
# (render/object_transport.h); a build without background fits waits for the
# fit in the frame. Figures from the window's --stats `frame_ms`: frames
# made, the slowest after the start-up one, the median; and the session's
# wall time (the script waits for the frame with the fit each time).
#
#   bench/view_new_material.sh [ROUNDS] [OTHER_TSIS]
#       writes bench/results/view_new_material.md; OTHER_TSIS, a second
#       binary (e.g. an older build), run interleaved with this one.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/bench/common.sh"
command -v xvfb-run >/dev/null || { echo "$0: needs xvfb-run (Debian: xvfb)" >&2; exit 1; }
rounds=${1:-3}
other=${2:-}
out="$results/view_new_material.md"
{
    echo "frame 2"
    for i in 1 2 3 4 5; do echo "set sigma-a 0.0$((i + 1))3,0.1,0.2"; done
    echo "orbit 6 0"
    echo close
} >"$tmp/session.script"
load=$(cut -d' ' -f1-3 /proc/loadavg)
: >"$tmp/rows"
for r in $(seq "$rounds"); do
    [ -t 2 ] && printf 'round %s of %s\r' "$r" "$rounds" >&2
    for bin in "$tsis" $other; do
        rm -rf "$tmp/cache"
        mkdir "$tmp/cache"
        start=$(date +%s.%N)
        TSIS_CACHE_DIR="$tmp/cache" xvfb-run -a "$bin" view --script "$tmp/session.script" \
            --stats "$tmp/stats.json" >/dev/null 2>&1
        end=$(date +%s.%N)
        python3 -c "
import json, statistics, sys
f = json.load(open(sys.argv[1]))['frame_ms']
print(sys.argv[2], len(f), max(f[1:]), statistics.median(f[1:]), float(sys.argv[4]) - float(sys.argv[3]))
" "$tmp/stats.json" "$bin" "$start" "$end" >>"$tmp/rows"
    done
done
[ -t 2 ] && printf '%*s\r' 20 '' >&2
python3 - "$tmp/rows" "$rounds" "$load" "$(cut -d' ' -f1-3 /proc/loadavg)" >"$out" <<'PY'
import sys
import time

rounds, load_start, load_end = sys.argv[2:]
print("# A new material in `tsis view`: the frames while its transport is fitted\n")
print(f"Made by `bench/view_new_material.sh {rounds}` on {time.strftime('%Y-%m-%dT%H:%MZ', time.gmtime())};"
      f" load average {load_start} at the start, {load_end} at the end. builtin:default, 512²,"
      " pyramid, the window under xvfb-run, an empty cache each session: 2 frames, 5 × `set"
      " sigma-a` (each a material never fitted), 1 × `orbit 6 0`. From the window's --stats"
      " `frame_ms`: the frames made, the slowest after the start-up one, their median; the"
      " session's wall time. Median over the rounds, each round's value in brackets.\n")
print("| binary | frames | slowest ms | median ms | session s |")
print("|---|---|---|---|---|")
PY
python3 "$root/bench/rounds_table.py" "$tmp/rows" 0.0 0.0 0.0 1.1 >>"$out"
cat "$out"
