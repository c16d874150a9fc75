#!/bin/bash
# The two-atlas brain (JHU white-matter tracts laid over the Colin27/AAL
# brain through meshes/brain_tracts.map) made by meshes/brain_tracts.sh
# into OUTPUT, then checked: five named labels, tracts meshed with a volume
# near the image's, and the mesh, skull and name table identical to the
# committed ones that prm/brain_tracts.prm uses.
#
# usage: run_brain_tracts_mesh.sh BUILD_DIRECTORY OUTPUT_DIRECTORY
set -eu
build=$1
out=$2
rm -rf "$out"
BUILD=$build meshes/brain_tracts.sh "$out" | tee "$out.log"
fail() { echo "FAIL: $1"; exit 1; }
grep -q "voxels from .*JHU-WhiteMatter-labels-1mm" "$out.log" || fail "no voxel from the JHU atlas"
for name in cerebrum tumour cerebellum brainstem tracts; do
  grep -qE "label [0-9]+ \($name\): [1-9][0-9]* tetrahedra" "$out.log" || fail "$name has no tetrahedron"
done
# The tracts' meshed volume within 10 % of their voxels'.
sed -n 's/.*(tracts): [0-9]* tetrahedra, \([0-9.]*\) cm^3 (image \([0-9.]*\) cm^3)/\1 \2/p' "$out.log" |
  awk '{ print "tracts: meshed " $1 " cm^3, image " $2 " cm^3"; exit !($1 > 0.9 * $2 && $1 < 1.1 * $2) }' ||
  fail "the tracts' meshed volume is far from the image's"
for f in brain_tracts.msh brain_tracts_skull.off brain_tracts_names.txt; do
  cmp -s "$out/$f" "meshes/$f" || fail "the regenerated $f differs from meshes/$f"
done
echo "ok"
