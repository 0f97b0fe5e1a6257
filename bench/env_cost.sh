#!/usr/bin/env bash
# The environment light's cost per frame (--env, docs/design.md §10), side by
# side in one run: the same scene with and without data/env/sky.hdr,
#  * the lighting changing every frame (`tsis animate --orbit`: the lights and
#    the map turn; the flux atlas is redrawn, the map re-projected, no ray cast),
#  * the camera moving (`tsis render --frames N`: the lighting is reused),
# and the once-per-mesh transfer (the first frame's env_transfer_ms).
# Then every method's error under the sky against the reference
# (volumetric included: the dipole's own error, not the method's).
# Writes bench/results/env_cost.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/bench/common.sh"
sky="$root/data/env/sky.hdr"
out="$results/env_cost.md"
frames=${ENV_BENCH_FRAMES:-16}
{
    echo "# Environment light cost (\`--env\`)"
    echo
    echo "Made by \`bench/env_cost.sh\` on $(date -u +%Y-%m-%dT%H:%MZ); $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores."
    echo "512², atlas 512², default method; lighting turns: the median render ms of the frames after the first; camera moves: the last of --frames. Load (1 min) at the start: $(cut -d' ' -f1 /proc/loadavg)."
    echo
    echo "The default scene's two lights in every column; \"+ sun\" adds the sky's sun as a plain directional light, \"+ env\" adds --env data/env/sky.hdr (its sun and its residual)."
    echo
    echo "| mesh | change | lights ms | + sun ms | + env ms | env cost ms | residual cost ms (env − sun) |"
    echo "|---|---|---|---|---|---|---|"
} >"$out"
steady() {  # median ms of the frames after the first in an animate stats file (robust to a busy machine)
    python3 -c "import json,sys,statistics; f=json.load(open(sys.argv[1]))['per_frame']; print('%.1f' % statistics.median(x['render_ms'] for x in f[1:]))" "$1"
}
# The default scene's lights written out (so that --env adds to them instead
# of replacing them) and the sky's sun as a plain light (make_sky.py: 30° up,
# 20° right of −z, 1.5 W/mm²): "+ env" minus "+ sun" is the residual's cost.
lights="--light point:-5.85,9.75,-13:298.3,298.3,298.3 --light dir:0.6,-0.4,-1:0.12,0.12,0.12"
sun="--light dir:-0.2962,-0.5,0.8138:1.5,1.43,1.28"
for mesh in builtin:default cow; do
    declare -A a c
    for k in lights sun env; do
        case $k in
            lights) extra="$lights" ;;
            sun) extra="$lights $sun" ;;
            env) extra="$lights --env $sky" ;;
        esac
        "$tsis" animate --mesh "$mesh" --frames "$frames" --orbit $extra -o "$tmp/a$k" --stats "$tmp/a$k.json" 2>/dev/null
        a[$k]=$(steady "$tmp/a$k.json")
        "$tsis" render --mesh "$mesh" --frames "$frames" $extra -o "$tmp/c$k.png" --stats "$tmp/c$k.json" 2>/dev/null
        c[$k]=$(number total "$tmp/c$k.json")
    done
    "$tsis" render --mesh "$mesh" $lights --env "$sky" --no-reuse-lighting --frames 3 -o "$tmp/t.png" --stats "$tmp/t.json" 2>/dev/null
    "$tsis" render --mesh "$mesh" $lights --env "$sky" -o "$tmp/t1.png" --stats "$tmp/t1.json" 2>/dev/null
    row() { python3 -c "import sys; a,b,c=map(float,sys.argv[1:4]); print('| %s | %s | %.1f | %.1f | %.1f | %.1f | %.1f |' % (sys.argv[4], sys.argv[5], a, b, c, c-a, c-b))" "$@"; }
    row "${a[lights]}" "${a[sun]}" "${a[env]}" "$mesh" "lighting turns (animate --orbit)" >>"$out"
    row "${c[lights]}" "${c[sun]}" "${c[env]}" "$mesh" "camera moves (lighting reused; --frames $frames, last)" >>"$out"
    echo "| $mesh | per lighting change: env_irradiance_ms $(number env_irradiance_ms "$tmp/t.json"); once per mesh: env_transfer_ms $(number env_transfer_ms "$tmp/t1.json") ($(number env_transfer_texels "$tmp/t1.json") texels traced) | | | | | |" >>"$out"
done
{
    echo
    echo "Per lighting change the map is projected on 16 harmonics (one pass over"
    echo "its texels) and each atlas texel takes one 16-term dot product per"
    echo "channel (env_irradiance_ms in --stats), then the texture is uploaded;"
    echo "no ray is cast after the first frame."
    echo
    echo "## Every method against the reference under data/env/sky.hdr"
    echo
    echo "builtin:default, skin1, 256², --env alone, radiosity; rel. RMSE over covered pixels (\`tsis compare --mask coverage\`), and the same without --env (the scene's own lights) beside it."
    echo "ltsm, tsm and the hybrid's local part read only the lights' maps (the sun): the renderer adds the residual by a texture-space run over its flux alone; lss reads it per atlas texel in its G-buffer (design §12)."
    echo "volumetric is the physical truth the dipole approximates: its difference is the dipole's, not the environment's."
    echo
    echo "| method | rel. RMSE vs reference, --env sky.hdr | without --env |"
    echo "|---|---|---|"
} >>"$out"
error() {  # rel. RMSE (percent) of method $1 with options $2 against the reference in $3
    "$tsis" render $2 --width 256 --height 256 --method $1 -o "$tmp/m.png" --aov "$tmp/m" 2>/dev/null
    e=$("$tsis" compare "$tmp/m/radiosity.exr" "$3/radiosity.exr" --mask "$3/coverage.exr" --json | sed -n 's/.*"rel_rmse": *\([-0-9.eE+]*\).*/\1/p')
    python3 -c "print('%.2f%%' % (100 * $e))"
}
"$tsis" render --env "$sky" --width 256 --height 256 --method reference -o "$tmp/r.png" --aov "$tmp/ref_env" 2>/dev/null
"$tsis" render --width 256 --height 256 --method reference -o "$tmp/r.png" --aov "$tmp/ref" 2>/dev/null
for m in pyramid tsis hybrid mis ltsm tsm lss hierarchical "volumetric --spp 64"; do
    echo "| $m | $(error "$m" "--env $sky" "$tmp/ref_env") | $(error "$m" "" "$tmp/ref") |" >>"$out"
done
cat "$out"
