#!/bin/bash
# Benchmark: the direct inverse (Inverse problem/Method = direct, the
# default: Newton on the equilibrium at the target with the rest shape as
# unknown, then the fixed point's check) against the fixed point (Anderson,
# consistent tangent), on the inverse column (P2, closed-form rest
# shape), the cantilever (large rotations), prm/brain.prm and
# prm/brain_skull_contact.prm (0.5 mm skull, no support), in one run.
# Prints a markdown table: converged, rest-shape updates, forward solves,
# forward Newton steps, direct Newton steps and Jacobian products, final
# mean and max error against the target (and the rest shape's L2 error
# against the closed form for the column), wall time and the ratio of
# times. Fails unless both methods converge on every scene and the direct
# inverse leaves the fixed point no rest-shape update on the column and
# the brain (the figure it stands for; not a time).
#
# usage: benchmarks/direct_inverse/run.sh [--coarse]
#   --coarse: the column (P2, no refinement) and prm/brain.prm only (the
#   version run in the tests)
# Run from the repository root after building (build/restshape).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/direct_inverse}
coarse=false
[ "${1:-}" = "--coarse" ] && coarse=true
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

scenes=("column:tests/scenes/column_inverse_p2.prm" "brain:prm/brain.prm")
$coarse || scenes+=("cantilever:tests/scenes/cantilever_prestress.prm"
  "brain_skull_contact:prm/brain_skull_contact.prm")
echo "machine: $(machine)"
echo
echo "| scene | method | converged | rest-shape updates | forward solves | forward Newton steps | direct Newton steps | Jacobian products | mean / max error (mm) | rest L2 error | wall s | time / fixed point |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for entry in "${scenes[@]}"; do
  name=${entry%%:*}
  prm=${entry#*:}
  sets=(--set "Scenario/Enabled=false")
  [ "$name" = column ] && sets+=(--set "Adaptive refinement/Cycles=0")
  for method in "fixed point" direct; do
    dir=$out/${name}_${method// /_}
    "$exe" "${sets[@]}" --set "Inverse problem/Method=$method" \
      --set "Output/Directory=$dir" "$prm" >"$dir.log" 2>&1
    s=$dir/summary.json
    converged=$(value converged "$s")
    [ "$converged" = "true" ] || status=1
    updates=$(value inverse_iterations "$s")
    wall=$(value wall_seconds "$s")
    [ "$method" = "fixed point" ] && wall0=$wall
    steps=$(value direct_inverse_newton_steps "$s")
    products=$(value direct_inverse_jacobian_products "$s")
    l2=$(value rest_l2_error_relative "$s")
    if [ "$method" = direct ] && [ "$name" != cantilever ] && [ "$name" != brain_skull_contact ] &&
      [ "$updates" != 0 ]; then
      echo "FAIL: $name: the fixed point needed $updates rest-shape updates after the direct inverse"
      status=1
    fi
    awk -v n="$name" -v m="$method" -v c="$converged" -v u="$updates" \
      -v f="$(value forward_solves "$s")" -v nw="$(value newton_iterations "$s")" \
      -v st="${steps:--}" -v p="${products:--}" -v e="$(value mean_error_mm "$s")" \
      -v x="$(value max_error_mm "$s")" -v l="${l2:--}" -v w="$wall" -v w0="$wall0" \
      'BEGIN { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %.2g / %.2g | %s | %.2f | %.2f |\n", n, m, c, u, f, nw, st, p, e, x, l, w, w / w0 }'
  done
done
exit $status
