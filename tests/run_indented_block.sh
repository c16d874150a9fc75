#!/bin/bash
# Step-44's indented block (prm/indented_block.prm): restshape's mixed Q1-P0
# element against deal.II's step-44 itself (tests/peers/step-44, the same
# Q1-P0 three-field formulation, the same 8^3 mesh, law and load), node by
# node, and the block's volume change at nu = 0.4999 (under 0.01 %).
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
cat >"$out/step-44/parameters.prm" <<'PRM'
subsection Finite element system
  set Polynomial degree = 1
  set Quadrature order  = 2
end
subsection Geometry
  set Global refinement   = 3
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
(cd "$out/step-44" && "$peer" >step-44.log 2>&1) ||
  { echo "FAIL: step-44: exit $?"; tail -n 5 "$out/step-44/step-44.log"; exit 1; }
# Both converged: restshape's summary, step-44's last force residual.
grep -q '"converged": true' "$out/restshape/summary.json" ||
  { echo "FAIL: restshape did not converge"; exit 1; }
/usr/bin/python3 "$here/check_indented_block.py" "$out/step-44/solution-3d-10.vtu" \
  "$out/restshape/solution-0000.vtu" --tolerance 5e-7 --volume 1e-4
