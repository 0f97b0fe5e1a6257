#!/usr/bin/env bash
# Builds the fuzz targets with clang (build-fuzz/) and runs each for a share of
# a bounded time from its seed corpus: mesh_fuzz (the mesh parsers and the
# atlas), mtl_fuzz (.mtl text), gltf_materials_fuzz (a glTF's materials,
# textures, images, extensions) and image_fuzz (texture and env-map bytes).
# Usage: tests/fuzz/run.sh [SECONDS] [ARGS…]   (SECONDS in all, default 60;
# ARGS to every libFuzzer run, e.g. -seed=1 -runs=25000 for the CI replay).
# Findings land in build-fuzz/ as <target>-crash-*, -leak-*, -timeout-*, -oom-*;
# the corpora libFuzzer grows are kept in build-fuzz/corpus-<target> (the seeds
# stay as they are). Exits non-zero when any run has a finding.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
secs=${1:-60}
shift || true
build=$root/build-fuzz
fuzz=$root/tests/fuzz
cmake -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTSIS_BUILD_FUZZ=ON -DTSIS_BUILD_TESTS=OFF \
    -DTSIS_BUILD_BENCH=OFF >/dev/null
targets="mesh_fuzz mtl_fuzz gltf_materials_fuzz image_fuzz"
# shellcheck disable=SC2086
make -C "$build" -j2 $targets
# mesh_fuzz keeps half the time (the widest input space), the others a sixth each.
share() { case $1 in mesh_fuzz) echo $((secs / 2 > 5 ? secs / 2 : 5)) ;; *) echo $((secs / 6 > 5 ? secs / 6 : 5)) ;; esac; }
seeds() { case $1 in mesh_fuzz) echo "$fuzz/corpus" ;; *) echo "$fuzz/corpus_${1%_fuzz}" ;; esac; }
status=0
# Leaks inside the libraries tsis calls, not tsis' (lsan.supp says which).
export LSAN_OPTIONS="suppressions=$fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
for t in $targets; do
    mkdir -p "$build/corpus-$t"
    dict=()
    [ "$t" = mesh_fuzz ] && dict=(-dict="$fuzz/mesh.dict")
    echo "== $t ($(share $t) s)"
    # -close_fd_mask=2: the parsers' notes would flood the log; libFuzzer keeps its own reports.
    "$build/tests/fuzz/$t" "$build/corpus-$t" "$(seeds $t)" "${dict[@]}" \
        -max_total_time="$(share $t)" -rss_limit_mb=2048 -timeout=5 -close_fd_mask=2 \
        -print_final_stats=1 -artifact_prefix="$build/$t-" "$@" || status=1
done
exit $status
