#!/usr/bin/env bash
# The composite's cost with the environment's reflection (design §10) against
# a binary without it, side by side in one run: cow and the default scene
# under data/env/sky.hdr, 512², the camera still (--frames 16: the lighting
# is reused, the composite runs each frame; its ms of the last frame), seven
# alternating runs of each binary, the median of them (a loaded machine's
# spread is larger than the difference). Replaces the section
# "The composite under --env" at the end of bench/results/frame.md.
#
#   BEFORE=/path/to/old/tsis bench/env_reflection_cost.sh
# (TSIS, TSIS_BENCH_BUILD, TSIS_BENCH_RESULTS: bench/common.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/bench/common.sh"
[ -x "${BEFORE:-}" ] || { echo "$0: set BEFORE to a tsis binary without the env reflection" >&2; exit 1; }
sky="$root/data/env/sky.hdr"
median() { printf '%s\n' "$@" | sort -g | sed -n "$(($# / 2 + 1))p"; }
composite() {  # BINARY MESH OPTIONS...: the composite's ms of the last frame
    local bin=$1 mesh=$2
    shift 2
    "$bin" render --mesh "$mesh" --env "$sky" --frames 16 --stats "$tmp/s.json" -o "$tmp/x.png" "$@" 2>/dev/null
    number composite "$tmp/s.json"
}
out="$results/frame.md"
sed -i '/^## The composite under --env/,$d' "$out"
{
    echo "## The composite under --env (the environment's reflection)"
    echo
    echo "Made by \`bench/env_reflection_cost.sh\` on $(date -u +%Y-%m-%dT%H:%MZ); $(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1), $(nproc) cores. Load (1 min) at the start: $(cut -d' ' -f1 /proc/loadavg)."
    echo "512², --env data/env/sky.hdr, camera still, --frames 16 (the composite of the last frame); median of seven alternating runs. *before*: the lobe lit by the lights (the sky's sun) only; *now*: and by the prefiltered residual; *no lobe*: --no-specular. The prefiltering itself runs once per map and roughness (env_reflection_ms of the first frame)."
    echo
    echo "| mesh | before ms | now ms | no lobe ms | prefilter, first frame ms |"
    echo "|---|---|---|---|---|"
} >>"$out"
for mesh in builtin:default cow; do
    b=() a=() n=()
    for i in 1 2 3 4 5 6 7; do
        b+=("$(composite "$BEFORE" "$mesh")")
        a+=("$(composite "$tsis" "$mesh")")
        n+=("$(composite "$tsis" "$mesh" --no-specular)")
    done
    "$tsis" render --mesh "$mesh" --env "$sky" --stats "$tmp/p.json" -o "$tmp/x.png" 2>/dev/null
    printf '| %s | %.1f | %.1f | %.1f | %.0f |\n' "$mesh" "$(median "${b[@]}")" "$(median "${a[@]}")" \
        "$(median "${n[@]}")" "$(number env_reflection_ms "$tmp/p.json")" >>"$out"
done
sed -n '/^## The composite under --env/,$p' "$out"
