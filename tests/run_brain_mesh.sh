#!/bin/bash
# The brain pipeline on the real atlas (Debian's mricron-data): labelled
# image, coarse mesh and skull made by meshes/brain.sh into OUTPUT, then
# checked: the four labels are present, the mesh has the size and quality
# the committed meshes/brain_coarse.msh has, and the skull is accepted.
#
# usage: run_brain_mesh.sh BUILD_DIRECTORY OUTPUT_DIRECTORY
set -eu
build=$1
out=$2
rm -rf "$out"
BUILD=$build meshes/brain.sh coarse "$out" | tee "$out.log"
fail() { echo "FAIL: $1"; exit 1; }
for label in 1 2 3 4; do
  grep -q "label $label: [1-9][0-9]* tetrahedra" "$out.log" || fail "label $label has no tetrahedron"
done
# The committed mesh was made by the same command: same node and cell counts.
committed=$(awk '/^\$Nodes/{getline; n=$1} /^\$Elements/{getline; print n, $1; exit}' meshes/brain_coarse.msh)
made=$(awk '/^\$Nodes/{getline; n=$1} /^\$Elements/{getline; print n, $1; exit}' "$out/brain_coarse.msh")
echo "nodes and tetrahedra: made $made, committed $committed"
[ "$made" = "$committed" ] || fail "the regenerated mesh differs from meshes/brain_coarse.msh"
min_angle=$(sed -n 's/^quality: dihedral angles \([0-9.]*\) to.*/\1/p' "$out.log" | head -n 1)
awk -v a="$min_angle" 'BEGIN { exit !(a > 5) }' || fail "smallest dihedral angle $min_angle deg"
grep -q "^skull .*triangles" "$out.log" || fail "no skull"
cmp -s "$out/brain_skull_0.5.off" meshes/brain_skull_0.5.off ||
  fail "the regenerated 0.5 mm skull differs from meshes/brain_skull_0.5.off"
cmp -s "$out/brain_skull_cut_0.5.off" meshes/brain_skull_cut_0.5.off ||
  fail "the regenerated cutting skull differs from meshes/brain_skull_cut_0.5.off"
echo "ok"
