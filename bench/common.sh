# Shared by the bench scripts that drive the tsis binary; sourced after they
# set $root (the repository). Sets $build, $results and $tsis, makes the
# results folder and a temporary folder $tmp (removed on exit), and defines
# `number`.
#
# TSIS               an already built tsis binary: used as it is, nothing is built
# TSIS_BENCH_BUILD   the build folder otherwise (default build-bench)
# TSIS_BENCH_RESULTS the results folder (default bench/results)
build=${TSIS_BENCH_BUILD:-$root/build-bench}
results=${TSIS_BENCH_RESULTS:-$root/bench/results}
if [ -n "${TSIS:-}" ]; then
    [ -x "$TSIS" ] || { echo "$0: TSIS=$TSIS is not an executable file" >&2; exit 1; }
    tsis=$TSIS
else
    cmake -S "$root" -B "$build" >/dev/null
    make -C "$build" -j2 tsis >/dev/null
    tsis="$build/tsis"
fi
mkdir -p "$results"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# number KEY FILE: the first "KEY": number in a JSON file.
number() { sed -n "s/.*\"$1\": *\([-0-9.eE+]*\).*/\1/p" "$2" | head -n 1; }
