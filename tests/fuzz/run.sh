#!/usr/bin/env bash
# Builds the mesh parser fuzzer with clang (build-fuzz/) and runs it for a
# bounded time from the seed corpus. Usage: tests/fuzz/run.sh [SECONDS] [ARGS…]
# Findings land in build-fuzz/ as crash-*, leak-*, timeout-*, oom-*; the
# corpus libFuzzer grows is kept in build-fuzz/corpus (the seeds stay as they are).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
secs=${1:-60}
shift || true
build=$root/build-fuzz
cmake -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTSIS_BUILD_FUZZ=ON -DTSIS_BUILD_TESTS=OFF \
    -DTSIS_BUILD_BENCH=OFF >/dev/null
make -C "$build" -j2 mesh_fuzz
mkdir -p "$build/corpus"
# -close_fd_mask=2: the parsers' repair notes would flood the log; libFuzzer
# keeps its own reports.
"$build/tests/fuzz/mesh_fuzz" "$build/corpus" "$root/tests/fuzz/corpus" \
    -dict="$root/tests/fuzz/mesh.dict" -max_total_time="$secs" -rss_limit_mb=2048 -timeout=5 \
    -close_fd_mask=2 -print_final_stats=1 -artifact_prefix="$build/" "$@"
