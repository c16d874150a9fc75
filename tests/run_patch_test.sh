#!/bin/bash
# The patch test (tests/data/patch_test.prm, tests/check_patch_test.py):
# every element and formulation on a cube of 3 x 3 x 3 distorted cells
# (meshes/make_block.py --distort 0.3; tetrahedra: each hexahedron split
# into 6) in homogeneous uniaxial tension must reproduce the exact linear
# field, volume ratio and pressure of its law.
# usage: run_patch_test.sh RESTSHAPE OUTPUT_DIRECTORY [MPIEXEC]
#   with MPIEXEC the P1 and Q1 mixed cases run again on 2 ranks.
set -u
exe=$1
out=$2
mpiexec=${3:-}
here=$(dirname "$0")
python=/usr/bin/python3
rm -rf "$out"
mkdir -p "$out"
$python meshes/make_block.py "$out/hexahedra.msh" 3 10 --distort 0.3 || exit 1
$python meshes/make_block.py "$out/tetrahedra.msh" 3 10 --distort 0.3 --tetrahedra || exit 1
E=3000
t=500
status=0
extra=() # further --set options of the next case
linear=(--set "Discretization/Cell pressure=linear") # Q2-P1disc
# case NAME CELLS DEGREE FORMULATION LAW NU CHECK_LAW [LAUNCHER...]
case_() {
  local name=$1 cells=$2 degree=$3 formulation=$4 law=$5 nu=$6 check=$7
  shift 7
  local dir=$out/$name
  "$@" "$exe" --set "Output/Directory=$dir" --set "Mesh/File=$out/$cells.msh" \
    --set "Mesh/Cell type=$cells" --set "Discretization/Polynomial degree=$degree" \
    --set "Discretization/Formulation=$formulation" --set "Materials/Material law=$law" \
    --set "Materials/Poisson's ratio=$nu" --set "Materials/Young's modulus=$E" \
    --set "Surface traction/Traction=$t, 0, 0" --set "Solver/Check stability=false" \
    "${extra[@]}" tests/data/patch_test.prm >"$dir.log" 2>&1
  local code=$?
  echo "== $name: $cells, degree $degree, $formulation, $law, nu = $nu"
  if [ $code -ne 0 ]; then
    echo "FAIL: exit $code"
    tail -n 3 "$dir.log"
    status=1
    return
  fi
  $python "$here/check_patch_test.py" "$dir" --law "$check" --young $E --poisson "$nu" \
    --traction $t || status=1
}
for nu in 0.4999 0.49999; do
  case_ "p1_mixed_$nu" tetrahedra 1 mixed neo-Hookean $nu mixed-neo-Hookean
  case_ "p2_mixed_$nu" tetrahedra 2 mixed neo-Hookean $nu mixed-neo-Hookean
  case_ "q1_mixed_$nu" hexahedra 1 mixed neo-Hookean $nu mixed-neo-Hookean
  # Q2: by default a constant pressure per cell (Q2-P0), then Q2-P1disc.
  case_ "q2_mixed_$nu" hexahedra 2 mixed neo-Hookean $nu mixed-neo-Hookean
  extra=("${linear[@]}")
  case_ "q2_p1disc_mixed_$nu" hexahedra 2 mixed neo-Hookean $nu mixed-neo-Hookean
  extra=()
done
case_ p1_displacement tetrahedra 1 displacement neo-Hookean 0.3 neo-Hookean
case_ q2_displacement hexahedra 2 displacement neo-Hookean 0.3 neo-Hookean
for law in Ogden corotational; do
  case_ "p1_mixed_$law" tetrahedra 1 mixed $law 0.4999 none
  case_ "q1_mixed_$law" hexahedra 1 mixed $law 0.4999 none
  extra=("${linear[@]}")
  case_ "q2_p1disc_mixed_$law" hexahedra 2 mixed $law 0.4999 none
  extra=()
done
if [ -n "$mpiexec" ]; then
  case_ p1_mixed_2_ranks tetrahedra 1 mixed neo-Hookean 0.4999 mixed-neo-Hookean \
    $mpiexec --allow-run-as-root --oversubscribe -np 2
  case_ q1_mixed_2_ranks hexahedra 1 mixed neo-Hookean 0.4999 mixed-neo-Hookean \
    $mpiexec --allow-run-as-root --oversubscribe -np 2
  extra=("${linear[@]}")
  case_ q2_p1disc_mixed_2_ranks hexahedra 2 mixed neo-Hookean 0.4999 mixed-neo-Hookean \
    $mpiexec --allow-run-as-root --oversubscribe -np 2
  extra=()
fi
[ $status -eq 0 ] && echo "every element passed the patch test"
exit $status
