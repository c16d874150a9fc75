#!/bin/bash
# Results read by the programs users read them with (check_clients.py:
# VTK's XML readers, meshio, gmsh; render_result.py: VTK offscreen under
# xvfb-run).
#
# usage: run_clients.sh RESTSHAPE OUTPUT_DIRECTORY CASE
#   p2_brain:     the brain scene with P2 tetrahedra (forward solve): every
#                 file read, and a picture of the displacement that must
#                 show the brain in colours (OUTPUT_DIRECTORY/brain_p2.png)
#   large_labels: the column with labels 16,777,217 and 33,554,433 (Float32
#                 rounds them to 16,777,216 and 33,554,432): VTK and meshio
#                 must read them exactly
set -eu
exe=$1
out=$2
case_name=$3
here=$(cd "$(dirname "$0")" && pwd)
python=/usr/bin/python3
rm -rf "$out"
mkdir -p "$out"
fail() { echo "FAIL: $1"; exit 1; }
case $case_name in
p2_brain)
  "$exe" --set "Output/Directory=$out/run" --set "Discretization/Polynomial degree=2" \
    --set "Inverse problem/Enabled=false" --set "Scenario/Enabled=false" \
    --set "Solver/Check stability=false" prm/brain.prm >"$out/screen.log" 2>&1 ||
    fail "the P2 brain did not run: $(tail -n 3 "$out/screen.log")"
  "$python" "$here/check_clients.py" "$out/run"
  xvfb-run -a "$python" "$here/render_result.py" "$out/run/solution-0000.vtu" \
    displacement_mm "$out/brain_p2.png"
  ;;
large_labels)
  # column_tet.msh with its physical tags 1 and 2 renumbered.
  awk 'BEGIN { map[1] = 16777217; map[2] = 33554433 }
       /\$Elements/ { inside = 1; print; next }
       /\$EndElements/ { inside = 0 }
       inside && NF > 5 { $4 = map[$4]; $5 = map[$5] } { print }' \
    meshes/column_tet.msh >"$out/column_large_labels.msh"
  for degree in 1 2; do
    "$exe" --set "Output/Directory=$out/p$degree" --set "Mesh/File=$out/column_large_labels.msh" \
      --set "Boundary conditions/Fixed labels=33554433" --set "Verification/Exact displacement=" \
      --set "Discretization/Polynomial degree=$degree" prm/column.prm >"$out/p$degree.log" 2>&1 ||
      fail "the column did not run: $(tail -n 3 "$out/p$degree.log")"
    "$python" "$here/check_clients.py" "$out/p$degree"
    "$python" - "$out/p$degree/solution-0000.vtu" <<'PY'
import sys
import meshio
import vtk
from vtkmodules.util.numpy_support import vtk_to_numpy
reader = vtk.vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
vtk_labels = set(vtk_to_numpy(reader.GetOutput().GetCellData().GetArray('label')).tolist())
meshio_labels = set(meshio.read(sys.argv[1]).cell_data['label'][0].tolist())
print('labels read by VTK:', sorted(vtk_labels), 'by meshio:', sorted(meshio_labels))
expected = {16777217, 33554433}
sys.exit(0 if vtk_labels == expected and meshio_labels == expected else 1)
PY
  done
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
echo ok
