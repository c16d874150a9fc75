#!/bin/bash
# Where Solver/Linear solver = auto switches: one forward solve of the brain
# (prm/brain.prm without the skull, no inverse, no VTU) at 0, 1 and 2 global
# refinements (3.6k, 25k, 186k DoFs), with the direct solver and with CG +
# AMG, in one run: wall seconds, linear-solve seconds, peak memory and the
# ratios cg-amg / direct. Both must reach the same equilibrium (largest
# displacement to 1e-6 relative).
#
# usage: benchmarks/linear_solver_auto/run.sh [--coarse]
#   --coarse: no refinement only (the version run in the tests)
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/linear_solver_auto).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/linear_solver_auto}
levels="0 1 2"
[ "${1:-}" = --coarse ] && levels="0"
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

echo "machine: $(machine)"
echo
echo "| refinements | DoFs | solver | wall s | linear solve s | peak MB | wall cg/direct | memory cg/direct |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for r in $levels; do
  for solver in direct cg-amg; do
    dir=$out/${r}_$solver
    /usr/bin/time -f "%M" -o "$dir.mem" "$exe" --set "Inverse problem/Enabled=false" \
      --set "Contact/Obstacle file=" --set "Scenario/Enabled=false" \
      --set "Output/Write VTU=false" --set "Mesh/Global refinements=$r" \
      --set "Solver/Linear solver=$solver" --set "Output/Directory=$dir" \
      prm/brain.prm >"$dir.log" 2>&1 || status=1
    s=$dir/summary.json
    [ "$(value converged "$s")" = true ] || status=1
    wall=$(value wall_seconds "$s")
    mb=$(awk '{ printf "%.0f", $1 / 1024 }' "$dir.mem")
    u=$(value max_displacement_mm "$s")
    if [ "$solver" = direct ]; then
      wall0=$wall mb0=$mb u0=$u
    else
      awk -v a="$u" -v b="$u0" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6 * b) }' || {
        echo "FAIL: largest displacement $u mm with cg-amg, $u0 mm direct"
        status=1
      }
    fi
    awk -v r="$r" -v n="$(value n_dofs "$s")" -v so="$solver" -v w="$wall" \
      -v l="$(timer_seconds 'Linear solve' "$dir.log")" -v m="$mb" -v w0="$wall0" -v m0="$mb0" \
      'BEGIN { printf "| %s | %s | %s | %.2f | %s | %s | %.2f | %.2f |\n", r, n, so, w, l, m, w / w0, m / m0 }'
  done
done
exit $status
