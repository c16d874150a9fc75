#!/bin/bash
# restshape-mesh --close-sulci on the real atlas (Debian's mricron-data) at
# the medium sizes of meshes/brain.sh (6 mm cells, 8 mm facets): without
# closing the surface has pinched edges (two folds touching along an edge),
# with a 3 mm ball it has none, and the closing adds between 0.5 and 5 % of
# the labelled volume.
#
# usage: run_close_sulci.sh BUILD_DIRECTORY OUTPUT_DIRECTORY
set -eu
build=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
fail() { echo "FAIL: $1"; exit 1; }
pinched() { sed -n 's/^pinched boundary edges[^:]*: \([0-9]*\).*/\1/p' "$1"; }
for r in 0 3; do
  "$build"/restshape-mesh --image meshes/brain_labels.nii.gz --out "$out/medium_$r.msh" \
    --cell-size 6 --facet-size 8 --facet-distance 1.5 --close-sulci $r | tee "$out/medium_$r.log"
done
open=$(pinched "$out/medium_0.log")
closed=$(pinched "$out/medium_3.log")
echo "pinched boundary edges: $open without closing, $closed with --close-sulci 3"
[ -n "$open" ] && [ "$open" -gt 0 ] || fail "expected pinched edges without closing, got '$open'"
[ "$closed" = 0 ] || fail "expected no pinched edge with --close-sulci 3, got '$closed'"
percent=$(sed -n 's/.*(\([0-9.]*\) % of the labelled volume) added.*/\1/p' "$out/medium_3.log")
awk -v p="$percent" 'BEGIN { exit !(p > 0.5 && p < 5) }' || fail "closing added '$percent' % of the volume"
echo "ok"
