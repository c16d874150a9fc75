#!/bin/bash
# Step-44's indented block (prm/indented_block.prm): restshape's mixed Q1-P0
# element against deal.II's step-44 itself (tests/peers/step-44, the same
# Q1-P0 three-field formulation, the same 8^3 mesh, law and load), node by
# node, and the block's volume change at nu = 0.4999 (under 0.01 %); then
# restshape's Q2-P1disc against step-44's own element (degree 2) on 4^3
# cells, and Q2-P0 there, which must differ.
# usage: run_indented_block.sh RESTSHAPE STEP44 OUTPUT_DIRECTORY
set -eu
exe=$1
peer=$2
out=$3
here=$(dirname "$0")
rm -rf "$out"
mkdir -p "$out/step-44"
/usr/bin/python3 meshes/make_block.py "$out/block_8.msh" 8 1
"$exe" --set "Output/Directory=$out/restshape" --set "Mesh/File=$out/block_8.msh" \
  prm/indented_block.prm >"$out/restshape.log" 2>&1 ||
  { echo "FAIL: restshape: exit $?"; tail -n 5 "$out/restshape.log"; exit 1; }
# Step-44's parameters: its own defaults but Q1-P0 (degree 1, 2x2x2 Gauss
# points), 3 refinements (8^3 cells), p/p0 = 80 and the direct solver.
# step44_parameters DEGREE REFINEMENTS
step44_parameters() {
cat <<PRM
subsection Finite element system
  set Polynomial degree = $1
  set Quadrature order  = $(($1 + 1))
end
subsection Geometry
  set Global refinement   = $2
  set Grid scale          = 1e-3
  set Pressure ratio p/p0 = 80
end
subsection Linear solver
  set Max iteration multiplier = 2
  set Residual                 = 1e-6
  set Use static condensation  = false
  set Preconditioner type      = ssor
  set Preconditioner relaxation = 0.65
  set Solver type              = Direct
end
subsection Material properties
  set Poisson's ratio = 0.4999
  set Shear modulus   = 80.194e6
end
subsection Nonlinear solver
  set Max iterations Newton-Raphson = 10
  set Tolerance displacement        = 1.0e-6
  set Tolerance force               = 1.0e-9
end
subsection Time
  set End time       = 1
  set Time step size = 0.1
end
PRM
}
step44_parameters 1 3 >"$out/step-44/parameters.prm"
(cd "$out/step-44" && "$peer" >step-44.log 2>&1) ||
  { echo "FAIL: step-44: exit $?"; tail -n 5 "$out/step-44/step-44.log"; exit 1; }
# Both converged: restshape's summary, step-44's last force residual.
grep -q '"converged": true' "$out/restshape/summary.json" ||
  { echo "FAIL: restshape did not converge"; exit 1; }
/usr/bin/python3 "$here/check_indented_block.py" "$out/step-44/solution-3d-10.vtu" \
  "$out/restshape/solution-0000.vtu" --tolerance 5e-7 --volume 1e-4

# Q2-P1disc (Cell pressure = linear) against step-44's
# degree 2 (its Q2-P1disc, 3x3x3 Gauss points) on 4^3 cells.
mkdir -p "$out/step-44-q2"
/usr/bin/python3 meshes/make_block.py "$out/block_4.msh" 4 1
step44_parameters 2 2 >"$out/step-44-q2/parameters.prm"
(cd "$out/step-44-q2" && "$peer" >step-44.log 2>&1) ||
  { echo "FAIL: step-44 (degree 2): exit $?"; exit 1; }
for pressure in linear constant; do
  "$exe" --set "Output/Directory=$out/q2_$pressure" --set "Mesh/File=$out/block_4.msh" \
    --set "Discretization/Polynomial degree=2" \
    --set "Discretization/Cell pressure=$pressure" \
    prm/indented_block.prm >"$out/q2_$pressure.log" 2>&1 ||
    { echo "FAIL: restshape Q2 ($pressure): exit $?"; exit 1; }
  grep -q '"converged": true' "$out/q2_$pressure/summary.json" ||
    { echo "FAIL: restshape Q2 ($pressure) did not converge"; exit 1; }
done
echo "== Q2-P1disc against step-44's degree 2"
/usr/bin/python3 "$here/check_indented_block.py" "$out/step-44-q2/solution-3d-10.vtu" \
  "$out/q2_linear/solution-0000.vtu" --tolerance 5e-7 --volume 1e-4 || exit 1
echo "== Q2-P0 against step-44's degree 2: must differ"
if /usr/bin/python3 "$here/check_indented_block.py" "$out/step-44-q2/solution-3d-10.vtu" \
  "$out/q2_constant/solution-0000.vtu" --tolerance 5e-7 --volume 1e-4; then
  echo "FAIL: Q2-P0 matches step-44's Q2-P1disc: the comparison cannot tell elements apart"
  exit 1
fi
echo "(Q2-P0 differs, as it must)"
