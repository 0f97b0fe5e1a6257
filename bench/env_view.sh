#!/usr/bin/env bash
# Turning the --env map in `tsis view` against dragging a light and orbiting
# the camera, side by side in one run, under a virtual display (xvfb-run):
# scripted sessions of 20 steps each (`set env-rotate`, `light-drag 6 0`,
# `orbit 6 0`), the window's `--stats` fps. Writes bench/results/env_view.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/bench/common.sh"
command -v xvfb-run >/dev/null || { echo "$0: needs xvfb-run (Debian: xvfb)" >&2; exit 1; }
out="$results/env_view.md"
lights="--light point:-5.85,9.75,-13:298.3,298.3,298.3 --light dir:0.6,-0.4,-1:0.12,0.12,0.12"
env="--env $root/data/env/sky.hdr"
script() {  # script NAME COMMAND: 2 frames, 20 × COMMAND (%d: the step), close
    { echo "frame 2"; for i in $(seq 1 20); do printf "$2\n" $((6 * i)); done; echo close; } >"$tmp/$1.script"
}
script envrot "set env-rotate %d"
script drag "light-drag 6 0 # %d"
script orbit "orbit 6 0 # %d"
{
    echo "# Turning the environment in \`tsis view\`"
    echo
    echo "Made by \`bench/env_view.sh\` on $(date -u +%Y-%m-%dT%H:%MZ); $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)."
    echo "builtin:default, 512², pyramid; the default scene's two lights written out; 20 scripted steps each; fps = the window's frames after the first per second."
    echo
    echo "| session | fps | last frame gl_flux_atlas ms | env_irradiance_ms |"
    echo "|---|---|---|---|"
} >"$out"
for run in "lights, light drag|$lights|drag" "lights + env, light drag|$lights $env|drag" \
    "lights + env, env turn|$lights $env|envrot" "lights + env, camera orbit|$lights $env|orbit"; do
    IFS='|' read -r name opts sc <<<"$run"
    xvfb-run -a "$tsis" view $opts --script "$tmp/$sc.script" --stats "$tmp/s.json" >/dev/null 2>&1
    python3 -c "
import json, sys
d = json.load(open(sys.argv[1])); f = d['last_frame']
print('| %s | %.2f | %.1f | %s |' % (sys.argv[2], d['fps'], f['ms'].get('gl_flux_atlas', 0), '%.1f' % f['env_irradiance_ms'] if 'env_irradiance_ms' in f else '–'))" "$tmp/s.json" "$name" >>"$out"
done
cat "$out"
