#!/bin/bash
# Inexact Newton (Solver/Inexact Newton = true: Eisenstat-Walker linear
# tolerances) against the fixed linear tolerance (1e-8 relative in every
# Newton step), CG + ML AMG, on the brain forward solve of prm/brain.prm
# without VTU, both in one run of this script: wall time, Newton steps, CG
# iterations (total and per step), and the largest and mean displacement
# of both, whose difference must stay at the Newton tolerance's level.
#
# usage: benchmarks/scaling/inexact_newton.sh [--coarse]
#   --coarse: the committed coarse mesh only (the version run in the tests)
# Environment: RESTSHAPE (build/restshape), OUT
# (output/benchmarks/inexact_newton), CASES (default "coarse medium
# medium+1": meshes of meshes/brain.sh, +N refined N times globally), SET
# (one extra 'Section/Parameter=value', e.g. 'Contact/Obstacle file=').
set -u
exe=${RESTSHAPE:-build/restshape}
build=$(dirname "$exe")
out=${OUT:-output/benchmarks/inexact_newton}
cases=${CASES:-coarse medium medium+1}
[ "${1:-}" = --coarse ] && cases=coarse
mkdir -p "$out/meshes"
source "$(dirname "$0")/../common.sh"
mesh_file() {
  if [ "$1" = coarse ]; then
    echo meshes/brain_coarse.msh
  else
    [ -f "$out/meshes/brain_$1.msh" ] ||
      { cp -n meshes/brain_labels.nii.gz "$out/meshes/" && BUILD=$build meshes/brain.sh "$1" "$out/meshes" >/dev/null; }
    echo "$out/meshes/brain_$1.msh"
  fi
}
echo "machine: $(machine)"
echo
echo "| mesh | DoFs | linear tolerance | seconds | Newton steps | CG iterations | CG per step | max / mean displacement (mm) | time / fixed |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for c in $cases; do
  level=${c%+*}
  refinements=0
  [[ $c == *+* ]] && refinements=${c##*+}
  mesh=$(mesh_file "$level")
  fixed_seconds=""
  fixed_max=""
  for inexact in false true; do
    dir=$out/${c}_$inexact
    rm -rf "$dir"
    if ! "$exe" --set "Output/Directory=$dir" --set "Mesh/File=$mesh" --set "Mesh/Global refinements=$refinements" \
      --set "Inverse problem/Enabled=false" --set "Prestress comparison/Enabled=false" \
      --set "Output/Write VTU=false" --set "Solver/Linear solver=cg-amg" --set "Solver/Inexact Newton=$inexact" \
      ${SET:+--set "$SET"} prm/brain.prm >"$dir.log" 2>&1; then
      echo "| $c | failed ($inexact): $(tail -n 1 "$dir.log") |"
      status=1
      continue
    fi
    s=$dir/summary.json
    seconds=$(value wall_seconds "$s")
    newton=$(value newton_iterations "$s")
    per_step=$(value linear_iterations_per_newton_step "$s")
    max=$(value max_displacement_mm "$s")
    [ "$inexact" = false ] && { fixed_seconds=$seconds; fixed_max=$max; }
    printf '| %s | %s | %s | %.2f | %s | %.0f | %.1f | %.6f / %.6f | %.2f |\n' "$c" "$(value n_dofs "$s")" \
      "$([ "$inexact" = true ] && echo Eisenstat-Walker || echo 1e-8)" "$seconds" "$newton" \
      "$(awk -v a="$per_step" -v b="$newton" 'BEGIN { print a * b }')" "$per_step" "$max" \
      "$(value mean_displacement_mm "$s")" "$(awk -v a="$seconds" -v b="$fixed_seconds" 'BEGIN { print a / b }')"
    if [ "$inexact" = true ] && [ -n "$fixed_max" ]; then
      # Both solutions converged to |R|/|f| <= 1e-10: they must agree far
      # below the mesh's resolution.
      awk -v a="$max" -v b="$fixed_max" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6 * b) }' ||
        { echo "FAIL: $c: largest displacement $max mm (inexact) against $fixed_max mm (fixed)"; status=1; }
    fi
  done
done
exit $status
