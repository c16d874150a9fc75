#!/bin/bash
# An atlas through a label map and a name table to a scene that names its
# tissues: restshape-mesh --label-names (a .nii.txt table, tabs and CR/LF)
# --label-map (atlas names and labels to tissues 1 'cerebrum' and 7
# 'tumour') writes the names as $PhysicalNames; restshape solves a scene
# whose label lists use only names, reports them, writes label_names.txt,
# and its rest_shape.msh keeps the names, so that a forward run from it
# takes the same named scene.
#
# usage: run_label_map.sh BUILD_DIRECTORY OUTPUT_DIRECTORY
set -eu
build=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
fail() { echo "FAIL: $1"; exit 1; }
"$build"/restshape-mesh --image tests/data/atlas_int16.nii \
  --label-names tests/data/atlas_int16.nii.txt \
  --label-map tests/data/atlas_int16_map.txt \
  --out "$out/atlas_named.msh" --cell-size 4 --facet-size 4 \
  --facet-distance 0.5 | tee "$out/mesher.log"
grep -q "label 1 (cerebrum): [1-9][0-9]* tetrahedra" "$out/mesher.log" ||
  fail "no tissue 1 'cerebrum' in the mesher's report"
grep -q "label 7 (tumour): [1-9][0-9]* tetrahedra" "$out/mesher.log" ||
  fail "no tissue 7 'tumour' in the mesher's report"
grep -q '^3 7 "tumour"' "$out/atlas_named.msh" || fail "no \$PhysicalNames"
"$build"/restshape --set "Mesh/File=$out/atlas_named.msh" \
  --set "Output/Directory=$out/run" tests/data/atlas_named.prm | tee "$out/run.log"
grep -q "labels 1 (cerebrum, [1-9][0-9]* coarse cells) 7 (tumour, " "$out/run.log" ||
  fail "restshape does not name the labels"
grep -q '"converged": true' "$out/run/summary.json" || fail "not converged"
grep -qx "7 tumour" "$out/run/label_names.txt" || fail "no label_names.txt"
grep -q '^3 7 "tumour"' "$out/run/rest_shape.msh" || fail "rest shape lost the names"
"$build"/restshape --set "Mesh/File=$out/run/rest_shape.msh" \
  --set "Inverse problem/Enabled=false" \
  --set "Output/Directory=$out/round_trip" tests/data/atlas_named.prm | tee "$out/round_trip.log"
grep -q '"converged": true' "$out/round_trip/summary.json" || fail "round trip not converged"
echo ok
