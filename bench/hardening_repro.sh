#!/usr/bin/env bash
# Issue 22's reproductions (items 2, 3, 4, 5 and 8 of the input side) run
# against a tsis binary: one line per case with the exit code, wall time,
# peak memory and the last lines of stderr. For before/after figures.
#
# Usage: bench/hardening_repro.sh TSIS [ITEM…]   (items: 2 3 4 5 8 lib; default all)
# lib: issue 40's library cases (threads, fork, SIGINT, arrays from Python:
# bench/hardening_python.py) against TSIS's build's `import tsis`
# (DIR/python beside DIR/tsis); LIB_TIMEOUT bounds each (30 s).
# ATLAS_INPUTS, ATLAS_TIMEOUT, FRAMES, ANIM_TIMEOUT, REF_TIMEOUT narrow or bound
# the slow ones (a binary from before the fixes runs for hours on some).
# Item 2 plants folders in a private TMPDIR; the other owner's needs root.
set -u
B=$(realpath "$1"); shift
items=${*:-"2 3 4 5 8 lib"}
root=$(cd "$(dirname "$0")/.." && pwd)
in=$(mktemp -d)
work=$(mktemp -d)
trap 'rm -rf "$in" "$work"' EXIT
python3 "$root/bench/hardening_inputs.py" "$in"
cd "$in"
t() { # label timeout cmd...
  local label=$1 to=$2; shift 2
  /usr/bin/time -f "%e s, max RSS %M KB" -o "$work/time" timeout "$to" "$@" >"$work/out" 2>&1
  local rc=$?
  echo "$label: rc=$rc, $(tail -1 "$work/time") | $(grep -v '^\s*$' "$work/out" | grep -v '%' | tail -2 | tr '\n' ' ' | cut -c1-330)"
}
for item in $items; do case $item in
2)
  for plant in symlink other-owner; do
    rm -rf $work/pt; mkdir -p $work/pt/attacker; echo x > $work/pt/file
    if [ $plant = symlink ]; then ln -s $work/pt/attacker $work/pt/tsis-pocl-$(id -u)
    else mkdir $work/pt/tsis-pocl-$(id -u); chmod 0777 $work/pt/tsis-pocl-$(id -u); chown 65534:65534 $work/pt/tsis-pocl-$(id -u) || continue; fi
    t "item2 planted $plant" 600 env -u TSIS_CACHE_DIR -u POCL_CACHE_DIR XDG_CACHE_HOME=$work/pt/file/x HOME=$work/pt/file TMPDIR=$work/pt $B render --width 16 --height 16 --atlas-res 64 -o $work/pt/out.png
    echo "   files PoCL left in the planted folder: $(find -L $work/pt/tsis-pocl-$(id -u) -type f | wc -l) ($(find -L $work/pt/tsis-pocl-$(id -u) -name '*.so' | wc -l) .so)"
  done
  rm -rf $work/pt ;;
3)
  t "item3 multiparent.gltf (2^25)" 30 bash -c "ulimit -v 8000000; exec $B atlas --mesh multiparent.gltf"
  t "item3 instanced.gltf (3000x3000)" 120 bash -c "ulimit -v 8000000; exec $B atlas --mesh instanced.gltf --atlas-res 64"
  ;;
4)
  for f in ${ATLAS_INPUTS:-dup3000 dup6000 dup100000 dupperm100000 dupeps3000 dupeps30000 dupeps100000}; do
    rm -rf $work/c; t "item4 atlas $f.obj" ${ATLAS_TIMEOUT:-300} env TSIS_CACHE_DIR=$work/c $B atlas --mesh $f.obj --atlas build
  done; rm -rf $work/c ;;
5)
  for n in ${FRAMES:-1500 100000}; do
    rm -rf $work/anim
    t "item5 animate --frames $n (staging, then the missing mesh)" ${ANIM_TIMEOUT:-200} $B animate --frames $n -o $work/anim --mesh /nonexistent.obj --width 16 --height 16
  done; rm -rf $work/anim ;;
8)
  t "item8 glTF uri ../quad.bin" 30 $B atlas --mesh escape/sub/dotdot.gltf
  t "item8 glTF uri absolute (run from /)" 30 bash -c "cd / && exec $B atlas --mesh $in/escape/sub/absolute.gltf"
  rm -f fifo.obj zero.obj fifo.png; mkfifo fifo.obj fifo.png; ln -s /dev/zero zero.obj
  t "item8 FIFO as mesh" 10 $B atlas --mesh fifo.obj
  t "item8 /dev/zero as mesh" 10 bash -c "ulimit -v 4000000; exec $B atlas --mesh zero.obj"
  sed 's|"uri":"../quad.bin"|"uri":"fifo.bin"|' escape/sub/dotdot.gltf > escape/sub/fifo.gltf; rm -f escape/sub/fifo.bin; mkfifo escape/sub/fifo.bin
  t "item8 FIFO as glTF buffer" 10 $B atlas --mesh escape/sub/fifo.gltf
  t "item8 FIFO as compare input" 10 $B compare fifo.png fifo.png
  rm -f fifo.obj zero.obj fifo.png escape/sub/fifo.bin
  rm -rf $work/pc; mkdir -p $work/pc
  t "item8 POCL_CACHE_DIR= (empty)" 600 env POCL_CACHE_DIR= TSIS_CACHE_DIR=$work/pc $B render --width 16 --height 16 --atlas-res 64 -o $work/pc/out.png
  rm -rf $work/ac; env TSIS_CACHE_DIR=$work/ac $B atlas --mesh cow --atlas build >/dev/null 2>&1
  for e in $work/ac/atlas/*.atlas; do rm -f $e; mkdir -p $e/sub; done
  t "item8 atlas cache entry is a folder" 300 env TSIS_CACHE_DIR=$work/ac $B atlas --mesh cow --atlas build
  rm -rf $work/ac
  t "item8 reference --spacing 0.002" ${REF_TIMEOUT:-60} env TSIS_CACHE_DIR=$work/pc $B render --method reference --spacing 0.002 -o $work/pc/ref.png
  rm -rf $work/pc ;;
lib)
  /usr/bin/python3 "$root/bench/hardening_python.py" "$(dirname "$B")/python" ${LIB_TIMEOUT:-30} ;;
esac; done
