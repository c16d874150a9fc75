#!/bin/bash
# The floor: how far a run is from the least it could cost. The floor is
# one Newton step's unavoidable work: one assembly plus one linear solve of
# the kind the run uses (direct solver: a numeric factorisation and its
# solve, the small end; CG + AMG: an AMG set-up plus one CG solve, the big
# end). It is measured, for each mesh, degree and solver, in a forward solve
# of prm/brain.prm in the same run of this script (TimerOutput: seconds over
# calls of "Assembly" and "Linear solve", whose "AMG set-up" is split off
# and counted once; means over the Newton steps, the first of which also
# does the symbolic factorisation or the first AMG build). The forward
# solve and the whole inverse with both methods are then given in floors:
# "run / floor" is how many Newton steps' worth of unavoidable work the run
# costs.
#
# usage: benchmarks/floor/run.sh [--coarse]
#   --coarse: the forward solve of prm/brain.prm only (the version in the
#   tests); fails if it costs more than MAX_FLOORS_PER_STEP (5) floors per
#   Newton step: work besides assembly and linear solves (contact search,
#   output, set-up) must not dominate a small run.
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/floor),
# BUILD (build: the mesher for the medium brain mesh).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/floor}
build=${BUILD:-build}
max_floors_per_step=${MAX_FLOORS_PER_STEP:-5}
coarse=false
[ "${1:-}" = --coarse ] && coarse=true
mkdir -p "$out/meshes"
source "$(dirname "$0")/../common.sh"

# mesh[+refinements]:degree:linear solver
configurations=("coarse:1:direct")
$coarse || configurations+=("coarse:2:cg-amg" "medium+1:1:cg-amg")

mesh_file() {
  if [ "$1" = coarse ]; then
    echo meshes/brain_coarse.msh
  else
    [ -f "$out/meshes/brain_$1.msh" ] ||
      { cp -n meshes/brain_labels.nii.gz "$out/meshes/" &&
        BUILD=$build meshes/brain.sh "$1" "$out/meshes" >/dev/null; }
    echo "$out/meshes/brain_$1.msh"
  fi
}

seconds_of() { timer_seconds "$1" "$2" | awk '{ print $1 + 0 }'; }

run() { # directory mesh degree solver inverse method
  local refinements=0
  [[ $2 == *+* ]] && refinements=${2##*+}
  rm -rf "$1"
  "$exe" --set "Output/Directory=$1" --set "Mesh/File=$(mesh_file "${2%+*}")" \
    --set "Mesh/Global refinements=$refinements" \
    --set "Discretization/Polynomial degree=$3" --set "Solver/Linear solver=$4" \
    --set "Inverse problem/Enabled=$5" --set "Inverse problem/Method=$6" \
    --set "Scenario/Enabled=false" --set "Output/Write VTU=false" \
    prm/brain.prm >"$1.log" 2>&1
}

echo "machine: $(machine)"
echo
echo "| mesh | degree | DoFs | solver | one assembly (ms) | one linear solve (ms) | floor (ms) | run | Newton steps | seconds | run / floor |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for configuration in "${configurations[@]}"; do
  IFS=: read -r mesh degree solver <<<"$configuration"
  base=$out/$(echo "${mesh}_p${degree}_$solver" | tr -c 'A-Za-z0-9+\n' _)
  if ! run "$base.forward" "$mesh" "$degree" "$solver" false "fixed point"; then
    echo "| $mesh | $degree | failed: $(tail -n 1 "$base.forward.log") |"
    status=1
    continue
  fi
  log=$base.forward.log
  read -r assembly solve floor <<<"$(awk \
    -v ac="$(timer_calls Assembly "$log")" -v as="$(seconds_of Assembly "$log")" \
    -v lc="$(timer_calls 'Linear solve' "$log")" -v ls="$(seconds_of 'Linear solve' "$log")" \
    -v gc="$(timer_calls 'AMG set-up' "$log")" -v gs="$(seconds_of 'AMG set-up' "$log")" 'BEGIN {
      a = as / ac; s = (ls - gs) / lc; if (gc > 0) s += gs / gc; print a, s, a + s }')"
  runs=(forward)
  $coarse || runs+=("fixed point" direct)
  for method in "${runs[@]}"; do
    dir=$base.forward
    if [ "$method" != forward ]; then
      dir=$base.${method// /_}
      run "$dir" "$mesh" "$degree" "$solver" true "$method" ||
        { echo "| $mesh | $degree | $method failed: $(tail -n 1 "$dir.log") |"; status=1; continue; }
    fi
    s=$dir/summary.json
    steps=$(timer_calls 'Linear solve' "$dir.log")
    [ "$method" = direct ] && steps="$steps + $(value direct_inverse_newton_steps "$s") direct"
    wall=$(value wall_seconds "$s")
    awk -v m="$mesh" -v p="$degree" -v d="$(value n_dofs "$s")" -v so="$solver" -v a="$assembly" \
      -v l="$solve" -v f="$floor" -v r="$method" -v n="$steps" -v w="$wall" 'BEGIN {
        printf "| %s | %s | %s | %s | %.3g | %.3g | %.3g | %s | %s | %.3g | %.1f |\n",
          m, p, d, so, 1e3 * a, 1e3 * l, 1e3 * f, r, n, w, w / f }'
    if $coarse && awk -v w="$wall" -v f="$floor" -v n="$steps" -v x="$max_floors_per_step" \
      'BEGIN { exit !(w / f / n > x) }'; then
      echo "FAILED: the forward solve costs more than $max_floors_per_step floors per Newton step"
      status=1
    fi
  done
done
exit $status
