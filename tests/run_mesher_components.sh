#!/bin/bash
# restshape-mesh keeps every connected component and cavity: a ball of
# label 3 (radius 60 mm) holding a void of radius 10 mm and a ball of label
# 250 of radius 10 mm (tests/data/enclosed.nii.gz; CGAL 5.5's own initial
# points missed both). Each must be in the mesh with about its volume
# (4.19 cm^3), the void as the wall of a cavity; --seed must change the
# mesh and the same seed give the same one. A label filling the image to
# its border (tests/data/border_cube.nii, 1000 mm^3) keeps its outer half
# voxel (729 mm^3 without it; Mesh_3 rounds the cube's edges: 970 mm^3).
#
# usage: run_mesher_components.sh RESTSHAPE_MESH OUTPUT_DIRECTORY
set -u
mesher=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
for seed in 0 1; do
  "$mesher" --image tests/data/enclosed.nii.gz --cell-size 4 --seed $seed \
    --out "$out/enclosed_$seed.msh" >"$out/enclosed_$seed.log" 2>&1 ||
    { echo "FAIL: meshing with seed $seed failed"; cat "$out/enclosed_$seed.log"; exit 1; }
done
"$mesher" --image tests/data/enclosed.nii.gz --cell-size 4 --seed 0 \
  --out "$out/enclosed_again.msh" >/dev/null 2>&1 || { echo "FAIL: the second seed-0 run failed"; exit 1; }
cmp -s "$out/enclosed_0.msh" "$out/enclosed_again.msh" || { echo "FAIL: seed 0 twice gives two meshes"; exit 1; }
cmp -s "$out/enclosed_0.msh" "$out/enclosed_1.msh" && { echo "FAIL: --seed does not change the mesh"; exit 1; }
python3 - "$out/enclosed_0.log" <<'PY' || exit 1
import re, sys
log = open(sys.argv[1]).read()
exact = 4 / 3 * 3.141592653589793 * 10 ** 3 / 1000  # cm^3
m = re.search(r"label 250: image 1 component \(([0-9.]+) cm\^3\), mesh 1 component \(([0-9.]+) cm\^3\)", log)
if not m:
    sys.exit("FAIL: label 250 is not one component of the mesh:\n" + log)
inclusion = float(m.group(2))
m = re.search(r"boundary surfaces: 2 \(1 outer, 1 cavity walls\); cavities: image 1 component \(([0-9.]+) cm\^3\), mesh 1 component \(([0-9.]+) cm\^3\)", log)
if not m:
    sys.exit("FAIL: the void is not a cavity of the mesh:\n" + log)
cavity = float(m.group(2))
for what, v in (("inclusion", inclusion), ("cavity", cavity)):
    if abs(v / exact - 1) > 0.15:
        sys.exit(f"FAIL: the {what} has {v} cm^3, the ball {exact:.3f}")
print(f"enclosed: inclusion {inclusion} cm^3, cavity {cavity} cm^3 (ball {exact:.3f})")
PY
# The surfaces by role, as gmsh physical surfaces, read with meshio.
/usr/bin/python3 - "$out/enclosed_0.msh" <<'PY' || exit 1
import sys
import meshio
import numpy as np
m = meshio.read(sys.argv[1])
area = {}
for block, tags in zip(m.cells, m.cell_data["gmsh:physical"]):
    if block.type != "triangle":
        continue
    p = m.points[block.data]
    a = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    for t in (1, 2):
        area[t] = area.get(t, 0) + a[tags == t].sum()
names = {v[0]: k for k, v in m.field_data.items() if v[1] == 2}
wall, outer = area.get(2, 0), area.get(1, 0)
if names.get(1) != "outer_surface" or names.get(2) != "cavity_walls":
    sys.exit(f"FAIL: physical surface names {names}")
# The cavity wall is the void's sphere, the outer surface the ball's and
# the inclusion is inside (no surface).
for what, a, r in (("cavity wall", wall, 10), ("outer surface", outer, 60)):
    if abs(a / (4 * np.pi * r * r) - 1) > 0.1:
        sys.exit(f"FAIL: the {what} has {a:.0f} mm^2, the sphere {4 * np.pi * r * r:.0f}")
print(f"surfaces: outer {outer:.0f} mm^2, cavity wall {wall:.0f} mm^2")
PY
"$mesher" --image tests/data/border_cube.nii --cell-size 2 --facet-distance 0.25 --out "$out/cube.msh" >"$out/cube.log" 2>&1 ||
  { echo "FAIL: meshing the border cube failed"; cat "$out/cube.log"; exit 1; }
volume=$(sed -n 's/^  label 1: [0-9]* tetrahedra, \([0-9.]*\) cm^3.*/\1/p' "$out/cube.log")
awk -v v="$volume" 'BEGIN { exit !(v > 0.95 && v < 1.03) }' ||
  { echo "FAIL: the border cube has $volume cm^3, not 1"; cat "$out/cube.log"; exit 1; }
echo "ok: the border cube keeps $volume cm^3 of 1"
