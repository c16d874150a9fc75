#!/bin/bash
# An int16 atlas with labels above 255 (tests/data/atlas_int16.nii: 300 and
# 2035) meshed by restshape-mesh and solved by restshape: the mesh carries
# both labels as physical tags, the scene names them (a range and a
# default too), the solve converges and every label keeps its cells.
#
# usage: run_atlas_labels.sh BUILD_DIRECTORY OUTPUT_DIRECTORY
set -eu
build=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
fail() { echo "FAIL: $1"; exit 1; }
"$build"/restshape-mesh --image tests/data/atlas_int16.nii \
  --out "$out/atlas_int16.msh" --cell-size 4 --facet-size 4 \
  --facet-distance 0.5 | tee "$out/mesher.log"
for label in 300 2035; do
  grep -q "label $label: [1-9][0-9]* tetrahedra" "$out/mesher.log" ||
    fail "label $label has no tetrahedron"
done
"$build"/restshape --set "Mesh/File=$out/atlas_int16.msh" \
  --set "Output/Directory=$out/run" tests/data/atlas_int16.prm | tee "$out/run.log"
grep -q "labels 300 ([1-9][0-9]* coarse cells) 2035 ([1-9][0-9]* coarse cells)" "$out/run.log" ||
  fail "restshape does not see labels 300 and 2035"
grep -q '"converged": true' "$out/run/summary.json" || fail "not converged"
echo ok
