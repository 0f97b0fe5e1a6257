#!/usr/bin/env bash
# Proof that a refactor kept the pixels: renders the default scene and cow with
# every method (256², default options otherwise) with two tsis binaries and
# compares the PNG and radiosity EXR bytes.
#
#   bench/same_images.sh OLD_TSIS NEW_TSIS     exit 0 when every pair is identical
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -eq 2 ] || { echo "usage: $0 OLD_TSIS NEW_TSIS" >&2; exit 2; }
old=$1 new=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The old binary's methods, as its own error for an unknown one lists them.
methods=$({ "$old" render --method '?' 2>&1 || true; } | sed -n 's/.*available: //p' | tr -d ',')
differ=0
for scene in builtin:default cow; do
    mesh=$scene
    [ "$scene" = cow ] && mesh=$root/data/meshes/cow.off
    for m in $methods; do
        for side in old new; do
            bin=$old; [ $side = new ] && bin=$new
            "$bin" render --mesh "$mesh" --method "$m" --width 256 --height 256 \
                -o "$tmp/$side.png" --aov "$tmp/$side" >/dev/null 2>"$tmp/$side.err" ||
                { echo "$scene $m: $side failed: $(cat "$tmp/$side.err")"; differ=1; continue 2; }
        done
        if cmp -s "$tmp/old.png" "$tmp/new.png" &&
           cmp -s "$tmp/old/radiosity.exr" "$tmp/new/radiosity.exr"; then
            echo "$scene $m: identical"
        else
            echo "$scene $m: DIFFERENT"
            differ=1
        fi
    done
done
exit $differ
