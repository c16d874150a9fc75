#!/bin/bash
# Options of the iterative linear solver (CG + ML AMG) compared in one run
# on the brain forward solve of prm/brain.prm without VTU:
#   fixed    the fixed linear tolerance (1e-8 relative in every Newton step)
#            and a new AMG preconditioner in every Newton step (the default
#            until 2026-11-23; now inexact+lagged+plain)
#   inexact  Solver/Inexact Newton = true (Eisenstat-Walker tolerances)
#   reuse    Solver/AMG update = reuse aggregates (the aggregates of the
#            first step kept, the rest of the AMG recomputed)
#   lagged   Solver/AMG update = lagged (an earlier step's AMG until CG
#            slows down)
#   aggX     Solver/AMG aggregation threshold = X (default 0), e.g. agg0.02
#   plain    Solver/AMG prolongator = plain (unsmoothed aggregation)
#   and combinations joined by '+', e.g. inexact+lagged
# Reports wall time, Newton steps, CG iterations (total and per step), the
# seconds of the linear solves and of the AMG set-up within them
# (TimerOutput), the peak memory (max RSS, GNU time), and the largest and mean
# displacement, which must agree with the first variant's to 1e-6 (all
# converge to the Newton tolerance; with contact nodes on fixed planes, to
# their distance off the obstacle). Time ratios are against the first
# variant of the same mesh, for the whole run and for the linear solves
# (assembly, the same work in every variant, varies by 10-20 % from run to
# run on a shared machine: the linear-solve ratio is the sharper one).
#
# usage: benchmarks/scaling/solver_options.sh [--coarse]
#   --coarse: the committed coarse mesh only (the version run in the tests)
# Environment: RESTSHAPE (build/restshape), OUT
# (output/benchmarks/solver_options), CASES (default "coarse medium
# medium+1": meshes of meshes/brain.sh, +N refined N times globally),
# VARIANTS (default "fixed inexact reuse lagged inexact+lagged
# inexact+lagged+plain"), SET (one extra
# 'Section/Parameter=value', e.g. 'Contact/Obstacle file=').
set -u
exe=${RESTSHAPE:-build/restshape}
build=$(dirname "$exe")
out=${OUT:-output/benchmarks/solver_options}
cases=${CASES:-coarse medium medium+1}
variants=${VARIANTS:-fixed inexact reuse lagged inexact+lagged inexact+lagged+plain}
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
options() { # variant -> "inexact threshold prolongator amg_update"
  local inexact=false update=rebuild threshold=0 prolongator=smoothed part
  for part in ${1//+/ }; do
    case $part in
      fixed) ;;
      inexact) inexact=true ;;
      reuse) update="reuse aggregates" ;;
      lagged) update=lagged ;;
      agg*) threshold=${part#agg} ;;
      plain) prolongator=plain ;;
      *) echo "unknown variant part '$part' (expected fixed, inexact, reuse, lagged, plain or aggX)" >&2; return 1 ;;
    esac
  done
  echo "$inexact $threshold $prolongator $update"
}
echo "machine: $(machine)"
echo
echo "| mesh | DoFs | variant | seconds | Newton steps | CG iterations | CG per step | linear solve / AMG set-up (s) | peak memory (MB) | max / mean displacement (mm) | time / first | linear solve / first |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for c in $cases; do
  level=${c%+*}
  refinements=0
  [[ $c == *+* ]] && refinements=${c##*+}
  mesh=$(mesh_file "$level")
  first_seconds=""
  first_linear=""
  first_max=""
  for variant in $variants; do
    opts=$(options "$variant") || exit 1
    read -r inexact threshold prolongator update <<<"$opts"
    dir=$out/${c}_$variant
    rm -rf "$dir"
    if ! /usr/bin/time -f %M -o "$dir.rss" "$exe" --set "Output/Directory=$dir" --set "Mesh/File=$mesh" --set "Mesh/Global refinements=$refinements" \
      --set "Inverse problem/Enabled=false" --set "Scenario/Enabled=false" \
      --set "Output/Write VTU=false" --set "Solver/Linear solver=cg-amg" --set "Solver/Inexact Newton=$inexact" \
      --set "Solver/AMG update=$update" --set "Solver/AMG aggregation threshold=$threshold" \
      --set "Solver/AMG prolongator=$prolongator" ${SET:+--set "$SET"} prm/brain.prm >"$dir.log" 2>&1; then
      echo "| $c | failed ($variant): $(tail -n 1 "$dir.log") |"
      status=1
      continue
    fi
    s=$dir/summary.json
    seconds=$(value wall_seconds "$s")
    newton=$(value newton_iterations "$s")
    per_step=$(value linear_iterations_per_newton_step "$s")
    max=$(value max_displacement_mm "$s")
    linear=$(timer_seconds 'Linear solve' "$dir.log")
    planes=$(value fixed_plane_distance_mm "$s")
    planes=${planes:-0}
    [ -z "$first_seconds" ] && { first_seconds=$seconds; first_linear=$linear; first_max=$max; first_planes=$planes; }
    printf '| %s | %s | %s | %.2f | %s | %.0f | %.1f | %s / %s | %d | %.6f / %.6f | %.2f | %.2f |\n' "$c" "$(value n_dofs "$s")" \
      "$variant" "$seconds" "$newton" "$(awk -v a="$per_step" -v b="$newton" 'BEGIN { print a * b }')" "$per_step" \
      "$linear" "$(timer_seconds 'AMG set-up' "$dir.log")" "$(($(cat "$dir.rss") / 1024))" "$max" "$(value mean_displacement_mm "$s")" \
      "$(awk -v a="$seconds" -v b="$first_seconds" 'BEGIN { print a / b }')" \
      "$(awk -v a="$linear" -v b="$first_linear" 'BEGIN { print a / b }')"
    # All converged to the Newton tolerance: they must agree far below the
    # mesh's resolution, to 1e-6 relative; with contact nodes on fixed
    # planes (a crease whose planes kept changing, doc/contact.md), to the
    # larger of the two runs' distances of those nodes off the obstacle,
    # because which planes get fixed depends on the Newton path.
    awk -v a="$max" -v b="$first_max" -v p="$planes" -v q="$first_planes" \
      'BEGIN { d = a - b; if (d < 0) d = -d; t = 1e-6 * b; if (p > t) t = p; if (q > t) t = q; exit !(d <= t) }' ||
      { echo "FAIL: $c: largest displacement $max mm ($variant) against $first_max mm (first variant; fixed-plane distances $planes and $first_planes mm)"; status=1; }
  done
done
exit $status
