#!/bin/bash
# Adaptive refinement/Transfer solution: each cycle after the first starts
# from the previous cycle's solution. Two scenes on the soft cantilever of
# prm/cantilever.prm (large rotations, so Newton from the unloaded mesh needs
# many steps), each run with the transfer and without:
#
# 1. forward, Q1 hexahedra, one adaptive cycle (hanging nodes);
# 2. inverse, P1 tetrahedra, one global cycle (red refinement), E = 300 kPa,
#    by the fixed point (the direct inverse converges at the target in
#    either case: its fixed point's check then needs 1 Newton step).
#
# Expected: the same result (the displacement, the rest shape) to solver
# tolerance, and fewer Newton iterations in cycle 1 with the transfer.
#
# usage: run_transfer.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
fail() {
  echo "FAIL: $1"
  exit 1
}

run() { # name transfer extra --set arguments...
  local name=$1 transfer=$2
  shift 2
  "$exe" --set "Output/Directory=$out/$name" --set "Output/Write VTU=false" \
    --set "Discretization/Polynomial degree=1" --set "Adaptive refinement/Cycles=1" \
    --set "Adaptive refinement/Transfer solution=$transfer" "$@" \
    prm/cantilever.prm >"$out/$name.log" 2>&1 || {
    tail -n 20 "$out/$name.log"
    fail "restshape failed on $name"
  }
}

# Column @p 2 of the rows of CSV file @p 1 whose column @p 3 is @p 4, summed.
sum_where() {
  awk -F, -v col="$2" -v key="$3" -v value="$4" '
    NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == col) c = i; if ($i == key) k = i } }
    NR > 1 && $k == value { s += $c } END { print s + 0 }' "$1"
}

# 1. Forward, Q1, adaptive.
for t in true false; do
  run forward_$t $t --set "Mesh/Cell type=hexahedra" --set "Adaptive refinement/Strategy=adaptive"
done
with=$(sum_where "$out/forward_true/convergence.csv" newton_iterations cycle 1)
without=$(sum_where "$out/forward_false/convergence.csv" newton_iterations cycle 1)
echo "forward, Q1 adaptive, cycle 1: $with Newton iterations with the transfer, $without without"
[ "$with" -lt "$without" ] || fail "the transfer did not save Newton iterations"
grep -q "starting from the previous cycle's solution" "$out/forward_true.log" ||
  fail "cycle 1 did not say it starts from the previous solution"
for t in true false; do cut -d, -f6 "$out/forward_$t/convergence.csv" >"$out/forward_$t.max"; done
numdiff -q -r 1e-6 "$out/forward_true.max" "$out/forward_false.max" >/dev/null ||
  fail "the largest displacements differ: $(tr '\n' ' ' <"$out/forward_true.max") against $(tr '\n' ' ' <"$out/forward_false.max")"

# 2. Inverse, P1 tetrahedra, global refinement.
for t in true false; do
  run inverse_$t $t --set "Materials/Young's modulus=300000" \
    --set "Inverse problem/Enabled=true" --set "Inverse problem/Tolerance=1e-3" \
    --set "Inverse problem/Method=fixed point"
done
with=$(sum_where "$out/inverse_true/iterations.csv" newton_iterations cycle 1)
without=$(sum_where "$out/inverse_false/iterations.csv" newton_iterations cycle 1)
iterations() { awk -F, 'NR > 1 && $NF == 1' "$1/iterations.csv" | wc -l; }
echo "inverse, P1, cycle 1: $with Newton iterations in $(iterations "$out/inverse_true") forward" \
  "solves with the transfer, $without in $(iterations "$out/inverse_false") without"
[ "$with" -lt "$without" ] || fail "the transfer did not save Newton iterations"
# The two rest shapes: both within the inverse tolerance of the same fixed
# point (mm in the mesh file).
numdiff -q -a 2e-3 "$out/inverse_true/rest_shape.msh" "$out/inverse_false/rest_shape.msh" >/dev/null ||
  fail "the rest shapes differ by more than 2e-3 mm: $(numdiff -a 2e-3 "$out/inverse_true/rest_shape.msh" "$out/inverse_false/rest_shape.msh" | tail -n 3)"
echo "ok: same results, fewer Newton iterations with the transfer"
