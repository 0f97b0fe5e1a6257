#!/bin/sh
# Runs the benchmark programs and makes the plots (gnuplot; `apt-get install -y
# gnuplot-nox`). Results: bench/results/*.md, *.csv, *.png. Not part of the tests.
#
#   bench/run.sh [all|tables|error|kernels|handoff|scaling|frame|animate|plots]... [-- ARGS]
#
# ARGS go to every program (--quick: fewer configurations; --frames N).
# TSIS_BENCH_BUILD (default build-bench) and TSIS_BENCH_RESULTS override the
# build folder and the results folder.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${TSIS_BENCH_BUILD:-$root/build-bench}
results=${TSIS_BENCH_RESULTS:-$root/bench/results}
export TSIS_BENCH_RESULTS="$results"
what=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do what="$what $1"; shift; done
[ $# -gt 0 ] && shift
[ -z "$what" ] && what=" all"
[ "$what" = " all" ] && what="tables error kernels handoff scaling frame animate plots"

cmake -S "$root" -B "$build" >/dev/null
make -C "$build" -j2 tsis bench_tables bench_error bench_kernels bench_handoff bench_scaling bench_frame >/dev/null
mkdir -p "$results"

animate() {
    # The steady frame rate of `tsis animate`, everything included (scene
    # update, frame, PNG write), for the three kinds of change.
    tmp=$(mktemp -d)
    out="$results/animate.md"
    {
        echo "# Dynamic frames (\`tsis animate\`)"
        echo
        echo "Made by \`bench/run.sh animate\` on $(date -u +%Y-%m-%dT%H:%MZ); $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores."
        echo "One Renderer for the sequence; steady rate = frames after the first; 512², atlas 1024², N = 900."
        echo
        echo "| change | command | load (1 min) | first frame ms | steady fps |"
        echo "|---|---|---|---|---|"
    } >"$tmp/md"
    run() {
        name=$1; shift
        load=$(cut -d' ' -f1 /proc/loadavg)
        "$build/tsis" animate -o "$tmp/$name" --stats "$tmp/$name.json" "$@" 2>/dev/null
        first=$(grep '"first_ms"' "$tmp/$name.json" | sed 's/.*: *//; s/,//')
        fps=$(grep '"steady_fps"' "$tmp/$name.json" | sed 's/.*: *//; s/,//')
        printf '| %s | `tsis animate %s` | %s | %.0f | %.2f |\n' "$name" "$*" "$load" "$first" "$fps" >>"$tmp/md"
    }
    run "light orbit" --mesh cow --material marble --frames 12 --orbit
    run "size 10 → 70 mm" --mesh cow --material skin2 --frames 12 --size-to 70
    run "material" --mesh cow --frames 12 --materials marble,skin1,skimmilk,ketchup
    mv "$tmp/md" "$out.tmp" && mv "$out.tmp" "$out"
    rm -rf "$tmp"
    echo "wrote $out"
}

plots() {
    command -v gnuplot >/dev/null || { echo "bench/run.sh: gnuplot not found (apt-get install -y gnuplot-nox)" >&2; return 1; }
    tmp=$(mktemp -d)
    if [ -f "$results/error.csv" ]; then
        for c in $(tail -n +2 "$results/error.csv" | cut -d, -f1 | sort -u); do
            plot=""
            for m in $(tail -n +2 "$results/error.csv" | awk -F, -v c="$c" '$1 == c {print $2}' | awk '!s[$0]++'); do
                awk -F, -v c="$c" -v m="$m" '$1 == c && $2 == m {print $5, $8}' "$results/error.csv" >"$tmp/$c-$m"
                plot="$plot${plot:+, }'$tmp/$c-$m' using 1:(100*\$2) with linespoints lw 2 title '$m'"
            done
            gnuplot <<GP
set terminal pngcairo size 800,560 font ",11" noenhanced
set output '$results/error_$c.png'
set logscale xy
set grid
set xlabel 'frame time (ms, whole frame)'
set ylabel 'relative RMSE of radiance (%)'
set title '$c: error against time'
set key outside right
plot $plot
GP
        done
    fi
    if [ -f "$results/tables.csv" ]; then
        plot=""
        for m in tsis lss hybrid; do
            for mesh in $(tail -n +2 "$results/tables.csv" | awk -F, -v m="$m" '$1 == m {print $2}' | awk '!s[$0]++'); do
                awk -F, -v m="$m" -v mesh="$mesh" '$1 == m && $2 == mesh {print $5, $12}' "$results/tables.csv" >"$tmp/t-$m-$mesh"
                dt=1; [ "$m" = lss ] && dt=2; [ "$m" = hybrid ] && dt=3
                plot="$plot${plot:+, }'$tmp/t-$m-$mesh' using 1:2 with linespoints dt $dt lw 2 title '$m $mesh'"
            done
        done
        gnuplot <<GP
set terminal pngcairo size 900,600 font ",11" noenhanced
set output '$results/tables_integration.png'
set logscale xy
set grid
set xlabel 'N (samples; lss: per pixel)'
set ylabel 'integration fps'
set title 'Integration rate against N (Tables 4.2 / 4.4)'
set key outside right
plot $plot
GP
    fi
    if [ -f "$results/scaling.csv" ]; then
        awk -F, '$1 == "triangles" {print $3, $10, $2}' "$results/scaling.csv" | sort -n >"$tmp/tri"
        awk -F, '$1 == "pixels" {print $6, $7}' "$results/scaling.csv" | sort -n >"$tmp/pix"
        awk -F, '$1 == "atlas" {print $5, 100*$13, $10}' "$results/scaling.csv" | sort -n >"$tmp/atl"
        gnuplot <<GP
set terminal pngcairo size 1500,450 font ",11" noenhanced
set output '$results/scaling.png'
set multiplot layout 1,3
set grid
set logscale x
set xlabel 'triangles'
set ylabel 'gather ns per Rd evaluation'
set yrange [0:*]
set title 'tsis gather against mesh size (N = 900)'
plot '$tmp/tri' using 1:2 with linespoints lw 2 notitle, '' using 1:2:3 with labels offset 0,1 font ",8" notitle
set logscale xy
set yrange [*:*]
set xlabel 'covered pixels'
set ylabel 'gather ms'
set title 'against pixel count (cow, N = 900)'
plot '$tmp/pix' using 1:2 with linespoints lw 2 notitle
set logscale x 2
set logscale y
set xlabel 'atlas resolution'
set ylabel 'relative RMSE (%)'
set title 'against atlas resolution (cow, marble; Fig. 4.6)'
plot '$tmp/atl' using 1:2 with linespoints lw 2 notitle
unset multiplot
GP
    fi
    rm -rf "$tmp"
    echo "plots in $results"
}

for w in $what; do
    case $w in
        tables | error | kernels | handoff | scaling | frame) "$build/bench/bench_$w" "$@" ;;
        animate) animate ;;
        plots) plots ;;
        *) echo "bench/run.sh: unknown benchmark '$w'" >&2; exit 2 ;;
    esac
done
