#!/usr/bin/env bash
# Issue 22's reproductions (items 2, 3, 4, 5 and 8 of the input side) run
# against a tsis binary: one line per case with the exit code, wall time,
# peak memory and the last lines of stderr. For before/after figures.
#
# Usage: bench/hardening_repro.sh TSIS [ITEM…]   (items: 2 3 4 5 8 40 lib; default all)
# lib: issue 40's library cases (threads, fork, SIGINT, arrays from Python:
# bench/hardening_python.py) against TSIS's build's `import tsis`
# (DIR/python beside DIR/tsis); LIB_TIMEOUT bounds each (30 s).
# ONLY=REGEX runs the item-40 cases whose label matches.
# Item 40 (issue 40, hostile assets) also states what each case must give
# (exit code, a word of the message, a time bound): with CHECK=1 a case that
# does not is counted and the script exits 1 (the CTest hardening.assets).
# ATLAS_INPUTS, ATLAS_TIMEOUT, FRAMES, ANIM_TIMEOUT, REF_TIMEOUT narrow or bound
# the slow ones (a binary from before the fixes runs for hours on some).
# Item 2 plants folders in a private TMPDIR; the other owner's needs root.
set -u
B=$(realpath "$1"); shift
items=${*:-"2 3 4 5 8 40 lib"}
root=$(cd "$(dirname "$0")/.." && pwd)
in=$(mktemp -d)
work=$(mktemp -d)
trap 'rm -rf "$in" "$work"' EXIT
python3 "$root/bench/hardening_inputs.py" "$in"
cd "$in"
t() { # label timeout cmd...
  local label=$1 to=$2; shift 2
  local rc
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -f "%e s, max RSS %M KB" -o "$work/time" timeout "$to" "$@" >"$work/out" 2>&1
    rc=$?
  else  # GNU time missing (Debian's package "time"): wall time only
    local t0=$(date +%s.%N)
    timeout "$to" "$@" >"$work/out" 2>&1
    rc=$?
    awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f s\n", b - a }' >"$work/time"
  fi
  line="$label: rc=$rc, $(tail -1 "$work/time") | $(grep -v '^\s*$' "$work/out" | grep -v '%' | tail -2 | tr '\n' ' ' | cut -c1-330)"
  echo "$line"
}
fails=0
# c label rc word seconds cmd…: as t, then (CHECK=1) the exit code must be rc,
# the output must hold word ("" none) and the run take at most seconds.
c() {
  local label=$1 rc=$2 word=$3 secs=$4; shift 4
  [ -n "${ONLY:-}" ] && ! grep -qE -- "$ONLY" <<<"$label" && return 0
  local start=$(date +%s.%N)
  t "$label" $((${secs%.*} * 4 + 10)) "$@"
  local got=$(sed -n 's/.*: rc=\([0-9]*\),.*/\1/p' <<<"$line")
  local took=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
  if [ "${CHECK:-0}" = 1 ]; then
    if [ "$got" != "$rc" ] || { [ -n "$word" ] && ! grep -qF -- "$word" "$work/out"; } ||
       awk -v t="$took" -v s="$secs" 'BEGIN { exit !(t > s) }'; then
      echo "   FAIL: expected rc=$rc, '$word', <= $secs s (took $took s)"; fails=$((fails + 1))
    fi
  fi
}
# The log-average luminance a --stats run reports (lavg), for colour cases.
lavg() { python3 -c "import json,sys; print('%.5f' % json.load(open(sys.argv[1]))['lavg'])" "$1" 2>/dev/null || echo "-"; }
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
40)
  cd "$in/h40/a"
  # The thesis' model: these cases are about the files, not the model (no fit each).
  R="$B render --model thesis --width 16 --height 16 --atlas-res 64 -o $work/o.png"
  asset() { case $1 in mtl_*) echo "$1.obj" ;; *) echo "$1.gltf" ;; esac; }
  # Untimed warm-up: a fresh build's first render compiles its kernels (minutes on PoCL).
  $R --mesh builtin:sphere >/dev/null 2>&1
  # A device is found through its link out of the folder; let out, it is still no regular file.
  for k in mtl_fifo gltf_fifo; do
    c "item40 texture FIFO (${k%%_*})" 0 "is a FIFO, not a regular file" 60 $R --mesh $(asset $k)
  done
  for k in mtl_zero mtl_urandom gltf_zero gltf_urandom; do
    c "item40 texture /dev/${k#*_} (${k%%_*})" 0 "outside the asset's folder" 60 $R --mesh $(asset $k)
    c "item40 texture /dev/${k#*_} (${k%%_*}, --allow-outside-assets)" 0 "character device" 60 $R --mesh $(asset $k) --allow-outside-assets
  done
  c "item40 --env FIFO" 1 "FIFO" 5 $R --env ../sky_fifo.hdr
  for k in mtl_dotdot mtl_absolute mtl_link_out gltf_dotdot gltf_link_out; do
    c "item40 texture outside the folder (${k#*_}, ${k%%_*})" 0 "outside the asset's folder" 60 $R --mesh $(asset $k)
  done
  c "item40 mtllib ../outside.mtl" 0 "outside the asset's folder" 60 $R --mesh mtl_lib_outside.obj
  c "item40 texture ../ with --allow-outside-assets" 0 "" 60 $R --mesh mtl_dotdot.obj --allow-outside-assets
  c "item40 16384² PNG header as texture (mtl)" 0 "limit of 64 M pixels" 60 $R --mesh mtl_huge_png.obj
  c "item40 16000² JPEG header as texture (mtl)" 0 "limit of 64 M pixels" 60 $R --mesh mtl_huge_jpg.obj
  c "item40 16384² PNG header as texture (glTF)" 0 "limit of 64 M pixels" 60 $R --mesh gltf_huge_png.gltf
  c "item40 --env .hdr header 16384x8192" 1 "limit of 64 M pixels" 5 $R --env ../sky_huge.hdr
  c "item40 --env .png header 16384x8192" 1 "limit of 64 M pixels" 5 $R --env ../sky_huge.png
  c "item40 glTF 1,000 materials (unused)" 0 "" 60 $R --mesh gltf_1000.gltf
  c "item40 .mtl 100,000 newmtl (1 used)" 0 "" 60 $R --mesh mtl_100k.obj
  c "item40 .mtl 50 materials (49 unused)" 0 "" 60 $R --mesh mtl_50.obj
  echo "   notes of the 49 unused: $(grep -c "material 'u" "$work/out")"
  c "item40 extras.tsis sigma 1e300" 1 "must lie in [0, 10000] mm^-1" 60 $R --mesh sigma_1e300.gltf
  c "item40 extras.tsis sigma 1e-300" 1 "it must be at least 0.0001 mm^-1" 60 $R --mesh sigma_1e-300.gltf
  c "item40 extras.tsis mfp 1e-300" 1 "must be in [0.0001, 10000]" 60 $R --mesh mfp_1e-300.gltf
  c "item40 attenuationDistance 1e-300" 1 "attenuationDistance" 60 $R --mesh atten_1e-300.gltf
  c "item40 --sigma-s 1e300" 1 "must lie in [0, 10000]" 5 $R --sigma-s 1e300,1,1
  c "item40 --sigma-a 1e300" 1 "must lie in [0, 10000]" 5 $R --sigma-a 1,1e300,1
  c "item40 --mfp 1e-300" 1 "must be in [0.0001, 10000]" 5 $R --mfp 1e-300,1,1
  c "item40 .mtl UTF-8 BOM" 0 "" 60 $R --mesh mtl_bom.obj
  if grep -q "defined in no material library" "$work/out"; then echo "   BOM: first material hidden"; [ "${CHECK:-0}" = 1 ] && fails=$((fails + 1)); fi
  c "item40 .mtl Ni 1" 0 "Ni 1" 60 $R --mesh mtl_ni1.obj
  c "item40 .mtl doubled spaces in map_Kd" 0 "" 60 $R --mesh mtl_spaces.obj
  if grep -q "not found" "$work/out"; then echo "   doubled spaces: texture not found"; [ "${CHECK:-0}" = 1 ] && fails=$((fails + 1)); fi
  c "item40 glTF percent-encoded uri" 0 "" 60 $R --mesh gltf_percent.gltf
  if grep -q "not found" "$work/out"; then echo "   percent-encoded: texture not found"; [ "${CHECK:-0}" = 1 ] && fails=$((fails + 1)); fi
  c "item40 glTF baseColorFactor a string" 0 "baseColorFactor not 4 numbers" 60 $R --mesh gltf_factor_typo.gltf
  # Colour: the same texture RGB and RGBA of alpha 0 (lavg equal), a grey
  # 8-bit sky against the linear value it encodes (lavg ratio 1 after sRGB).
  $R --mesh mtl_spaces.obj --stats $work/s1.json >/dev/null 2>&1
  $R --mesh mtl_alpha0.obj --stats $work/s2.json >/dev/null 2>&1
  echo "   item40 RGBA alpha-0 texture: lavg $(lavg $work/s2.json) (opaque same colour: $(lavg $work/s1.json))"
  if [ "${CHECK:-0}" = 1 ] && [ "$(lavg $work/s1.json)" != "$(lavg $work/s2.json)" ]; then echo "   FAIL: alpha 0 darkened"; fails=$((fails + 1)); fi
  $R --mesh builtin:sphere --env ../sky188.png --stats $work/s3.json >/dev/null 2>&1
  echo "   item40 8-bit PNG sky of 188: lavg $(lavg $work/s3.json) (sRGB-decoded: 0.503 a texel; linear would be 0.737, 1.47x)"
  cd "$in" ;;
lib)
  /usr/bin/python3 "$root/bench/hardening_python.py" "$(dirname "$B")/python" ${LIB_TIMEOUT:-30} ;;
esac; done
[ "${CHECK:-0}" = 1 ] && { echo "item 40 checks failed: $fails"; [ $fails = 0 ]; }
