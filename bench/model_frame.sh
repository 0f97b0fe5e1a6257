#!/usr/bin/env bash
# The new default model's frame cost against the thesis' (issue 36: ≤ 1.15×
# with the light moving) and what --single-scatter adds to it: bench_frame
# --side-by-side for the default scene and cow, today's defaults, --model
# thesis and the defaults with --single-scatter interleaved, ROUNDS rounds of
# FRAMES frames each (medians of the whole frame); the fit is made before the
# first round (cached), so the rounds time frames only. Writes
# bench/results/model_frame.md.
#   bench/model_frame.sh [BUILD_DIR] [ROUNDS] [FRAMES]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
rounds=${2:-3}
frames=${3:-10}
out=bench/results/model_frame.md
bench=$build/bench/bench_frame
# The notes below the table (what changed when) stay.
notes=$(awk '/^\|/ {last = NR} {line[NR] = $0} END {for (i = last + 1; i <= NR; ++i) print line[i]}' "$out" 2>/dev/null || true)
run() { "$bench" --side-by-side --frames "$frames" "$@" 2>/dev/null | grep '^TSIS'; }
field() { sed -n "s/.*$1=\([0-9.]*\).*/\1/p"; }
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
{
  echo "# The default model's frame against the thesis' model"
  echo
  echo "Made by \`bench/model_frame.sh\` on $(date -u +%Y-%m-%dT%H:%MZ) (load $(cut -d' ' -f1 /proc/loadavg)): \`bench_frame --side-by-side --frames $frames\`, 512², today's defaults (\`--transport object\`), \`--model thesis\` and the defaults with \`--single-scatter\`, $rounds rounds interleaved; medians of the rounds' medians (ms); ratios to the thesis' model."
  echo
  echo "| scene | light moving: default / thesis / + single scatter | ratios | camera moving: default / thesis / + single scatter | ratios |"
  echo "|---|---|---|---|---|"
} > "$out"
for scene in "--mesh builtin:default" "--mesh cow --material marble"; do
  # shellcheck disable=SC2086
  run $scene >/dev/null  # the fit, once (cached)
  : > /tmp/model_frame_new; : > /tmp/model_frame_old; : > /tmp/model_frame_ss
  for ((r = 0; r < rounds; ++r)); do
    # shellcheck disable=SC2086
    run $scene >> /tmp/model_frame_new
    # shellcheck disable=SC2086
    run $scene --model thesis >> /tmp/model_frame_old
    # shellcheck disable=SC2086
    run $scene --single-scatter >> /tmp/model_frame_ss
  done
  ln=$(field light_moving_ms < /tmp/model_frame_new | median)
  lo=$(field light_moving_ms < /tmp/model_frame_old | median)
  cn=$(field camera_moving_ms < /tmp/model_frame_new | median)
  co=$(field camera_moving_ms < /tmp/model_frame_old | median)
  ls=$(field light_moving_ms < /tmp/model_frame_ss | median)
  cs=$(field camera_moving_ms < /tmp/model_frame_ss | median)
  ratios() { awk "BEGIN {printf \"%.3f / %.3f\", $1 / $2, $3 / $2}"; }
  echo "| \`$scene\` | $ln / $lo / $ls | $(ratios "$ln" "$lo" "$ls") | $cn / $co / $cs | $(ratios "$cn" "$co" "$cs") |" >> "$out"
done
if [[ -n "${notes//[[:space:]]/}" ]]; then printf '%s\n' "$notes" >> "$out"; fi
cat "$out"
