#!/bin/bash
# Discretization/Nodal pressure at the boundary = interior (the averaged
# nodal pressure whose boundary vertices give their share of each cell's
# volume to the cell's interior vertices):
# - the Lame shell at nu = 0.4999 on the 2 mm mesh (meshes/make_shell.py)
#   as accurate as P1 with displacements at nu = 0.3 (4.50 % against
#   5.27 %; the element with its own boundary volumes: 7.01 %);
# - the patch test (tests/check_patch_test.py: a distorted block of
#   tetrahedra pulled by a dead traction, the exact homogeneous state);
# - 2 MPI ranks give the nodes of 1 (the 4 mm shell, to 1e-7);
# - no note that the error stops falling (that of the element's own
#   boundary volumes).
# usage: run_nodal_boundary.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
out=$2
here=$(dirname "$0")
python=/usr/bin/python3
rm -rf "$out"
mkdir -p "$out"
interior="Discretization/Nodal pressure at the boundary=interior"
$python meshes/make_shell.py "$out/shell_2.msh" 10 20 2 2 || exit 1
$python meshes/make_block.py "$out/tetrahedra.msh" 3 10 --distort 0.3 --tetrahedra || exit 1
# shell NAME FORMULATION NU [launcher...]: the run's RMS error (%).
shell() {
  local name=$1 formulation=$2 nu=$3 mesh=${MESH:-$out/shell_2.msh}
  shift 3
  "$@" "$exe" --set "Output/Directory=$out/$name" --set "Mesh/File=$mesh" \
    --set "Discretization/Formulation=$formulation" --set "$interior" \
    --set "Materials/Poisson's ratio=$nu" --set "Solver/Check stability=false" \
    tests/data/lame_shell.prm >"$out/$name.log" 2>&1 ||
    { echo "FAIL: $name: exit $?" >&2; tail -n 3 "$out/$name.log" >&2; return 1; }
  $python "$here/check_lame_shell.py" "$out/$name/nodes.csv" --E 3000 --nu "$nu" \
    --p-inner 1 --support 1e3 --label "$name" | tee -a "$out/figures.txt" |
    sed -E 's/.*displacement ([0-9.]+) %.*/\1/'
}
status=0
reference=$(shell p1_0.3 displacement 0.3) || exit 1
error=$(shell p1_interior_0.4999 mixed 0.4999) || exit 1
if awk -v e="$error" -v r="$reference" 'BEGIN { exit !(e <= r) }'; then
  echo "ok: P1 mixed (interior) at nu = 0.4999: $error % (P1 at 0.3: $reference %)"
else
  echo "FAIL: P1 mixed (interior) at nu = 0.4999: $error % against $reference % for P1 at 0.3"
  status=1
fi
! grep -q "^Note: .*averaged nodal pressure's error stops" "$out/p1_interior_0.4999.log" ||
  { echo "FAIL: the note on the element's own boundary volumes with interior"; status=1; }
"$exe" --set "Output/Directory=$out/patch" --set "Mesh/File=$out/tetrahedra.msh" \
  --set "Mesh/Cell type=tetrahedra" --set "Discretization/Formulation=mixed" --set "$interior" \
  --set "Materials/Material law=neo-Hookean" --set "Materials/Poisson's ratio=0.4999" \
  --set "Materials/Young's modulus=3000" --set "Surface traction/Traction=500, 0, 0" \
  --set "Solver/Check stability=false" tests/data/patch_test.prm >"$out/patch.log" 2>&1 ||
  { echo "FAIL: patch test: exit $?"; tail -n 3 "$out/patch.log"; exit 1; }
$python "$here/check_patch_test.py" "$out/patch" --law mixed-neo-Hookean --young 3000 \
  --poisson 0.4999 --traction 500 || status=1
MESH=meshes/shell_4mm.msh shell ranks_1 mixed 0.4999 >/dev/null || exit 1
MESH=meshes/shell_4mm.msh shell ranks_2 mixed 0.4999 \
  mpirun --allow-run-as-root --oversubscribe -np 2 >/dev/null || exit 1
if numdiff -q -s ' \t\n,' -r 1e-7 -a 1e-12 "$out/ranks_1/nodes.csv" "$out/ranks_2/nodes.csv" >/dev/null; then
  echo "ok: 2 MPI ranks give the nodes of 1"
else
  echo "FAIL: 2 MPI ranks differ from 1"
  status=1
fi
cat "$out/figures.txt"
exit $status
