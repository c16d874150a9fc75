#!/bin/bash
# Where Solver/Linear solver = auto switches: runs of the brain with the
# direct solver (MUMPS) and with CG + AMG, back to back, for
#   free      prm/brain.prm without the skull (supports and stalk only),
#             P1 at 0, 1 and 2 global refinements (3.6k, 25k, 186k DoFs),
#             P2 at 0 (25k DoFs);
#   contact   prm/brain_skull_cut.prm (the skull 0.5 mm into the brain,
#             strict contact), stress-free from the image under the
#             scene's buoyed gravity, P1 at 0 and 1 refinements, P2 at 0;
#   inverse   prm/brain.prm as it is (the direct inverse, then the fixed
#             point with the skull), P1 at 0 and 1 refinements, P2 at 0;
#   tracts_free, tracts_contact, tracts_inverse
#             the same on another brain, that of prm/brain_tracts.prm
#             (4,115 nodes, five tissues: 12k DoFs P1, 91k P2), its
#             cutting skull made here by restshape-mesh as
#             meshes/brain_tracts.sh makes the scene's, 0.5 mm into the
#             brain; P1, and P2 without contact;
#   small_cavity, small_hertz, small_block, small_tube, cantilever_free
#             where the two cross, below the coarse brain: the contact
#             scenes prm/cantilever_in_cavity.prm, prm/hertz.prm,
#             prm/block_on_floor.prm and prm/column.prm inside
#             meshes/column_tube.off, P1 and P2, 567 to 28,611 DoFs, and
#             the slender cantilever of prm/cantilever.prm (10:1, no
#             contact); each run REPEATS times (3), the shortest wall time
#             counts;
# no scenario, no VTU. Prints wall seconds, the seconds of the solves
# (linear solves; the whole direct inverse), Newton steps (the direct
# inverse's steps and Jacobian products), the largest displacement, peak
# memory, the ratios cg-amg / direct of wall time and memory, and the
# difference of the potential energies (J).
# Without contact both solvers must reach the same equilibrium (largest
# displacement to 1e-6 relative). With contact the problem is not convex
# (the skull's cavity is not): both must converge with the strict contact
# conditions holding, but the inexact Newton steps of CG + AMG may end in
# a neighbouring stable equilibrium; the energy difference shows which is
# lower.
#
# usage: benchmarks/linear_solver_auto/run.sh [--coarse]
#   --coarse: P1 without refinement only, the series free, contact and
#             inverse (the tests' version)
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/
# linear_solver_auto), SERIES ("free contact inverse tracts_free
# tracts_contact tracts_inverse small_cavity small_hertz small_block
# small_tube cantilever_free"), REPEATS (3, for the small series and
# cantilever_free). Run from the repository root.
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/linear_solver_auto}
series=${SERIES:-free contact inverse tracts_free tracts_contact tracts_inverse small_cavity small_hertz small_block small_tube cantilever_free}
repeats=${REPEATS:-3}
[ "${1:-}" = --coarse ] && series=${SERIES:-free contact inverse}
coarse=false
[ "${1:-}" = --coarse ] && coarse=true
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

# cases SERIES: "degree:refinements" of a series.
cases() {
  $coarse && { echo "1:0"; return; }
  case $1 in
    free) echo "1:0 1:1 1:2 2:0" ;;
    tracts_free | small_hertz) echo "1:0 2:0" ;;
    tracts_*) echo "1:0" ;;
    small_cavity) echo "1:0 1:1 2:0 2:1" ;;
    small_block) echo "1:2 2:1 2:2" ;;
    small_tube) echo "1:1 1:2 2:1" ;;
    cantilever_free) echo "1:1 1:2 2:0 2:1" ;;
    *) echo "1:0 1:1 2:0" ;;
  esac
}

# The tracts brain's cutting skull and its contact scene, in $out/tracts.
tracts_scene() {
  local dir=$out/tracts bin
  bin=$(dirname "$exe")
  [ -f "$dir/contact.prm" ] && return
  mkdir -p "$dir"
  sed -e 's/--skull-gap 2/--skull-gap -0.5/' meshes/brain_tracts.sh >"$dir/make.sh"
  BUILD=$bin bash "$dir/make.sh" "$dir" >"$dir/make.log" 2>&1 || {
    echo "FAIL: the tracts skull ($dir/make.log)"
    exit 1
  }
  cat >"$dir/contact.prm" <<EOF
include prm/brain_tracts.prm
subsection Boundary conditions
  set Elastic support stiffness = 0
end
subsection Contact
  set Obstacle file  = $dir/brain_tracts_skull.off
  set Gap tolerance  = 0.01
  set Pull tolerance = 1
end
subsection Loads
  set Surface pressure = 0
end
EOF
}

# run SERIES DEGREE REFINEMENTS SOLVER DIR: one forward solve.
run() {
  local scene=prm/brain.prm
  local extra=(--set "Contact/Obstacle file=" --set "Inverse problem/Enabled=false")
  case $1 in
    contact)
      scene=prm/brain_skull_cut.prm
      extra=(--set "Loads/Surface pressure=0" --set "Inverse problem/Enabled=false") ;;
    inverse) extra=() ;;
    tracts_free) scene=prm/brain_tracts.prm ;;
    tracts_contact)
      tracts_scene
      scene=$out/tracts/contact.prm
      extra=(--set "Inverse problem/Enabled=false") ;;
    tracts_inverse) scene=prm/brain_tracts.prm extra=() ;;
    small_cavity) scene=prm/cantilever_in_cavity.prm extra=() ;;
    small_hertz) scene=prm/hertz.prm extra=() ;;
    small_block) scene=prm/block_on_floor.prm extra=() ;;
    cantilever_free) scene=prm/cantilever.prm extra=() ;;
    small_tube)
      scene=prm/column.prm
      extra=(--set "Contact/Obstacle file=meshes/column_tube.off") ;;
  esac
  /usr/bin/time -f "%M" -o "$5.mem" "$exe" \
    --set "Scenario/Enabled=false" --set "Output/Write VTU=false" \
    --set "Discretization/Polynomial degree=$2" \
    --set "Mesh/Global refinements=$3" --set "Solver/Linear solver=$4" \
    --set "Output/Directory=$5" "${extra[@]}" "$scene" >"$5.log" 2>&1
}

echo "machine: $(machine)"
echo
echo "| series | P | refinements | DoFs | solver | wall s | solve s | Newton steps | largest displacement mm | peak MB | wall cg/direct | memory cg/direct | energy cg - direct J |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for s in $series; do
  for c in $(cases "$s"); do
    p=${c%:*} r=${c#*:}
    for solver in direct cg-amg; do
      dir=$out/${s}_p${p}_r${r}_$solver
      # The small series: the shortest of several runs (each well under
      # a second, where another process's moment counts).
      n=1
      case $s in small_* | cantilever_free) n=$repeats ;; esac
      best=
      for ((i = 0; i < n; ++i)); do
        rm -rf "$dir"
        run "$s" "$p" "$r" "$solver" "$dir" || status=1
        w=$(value wall_seconds "$dir/summary.json")
        best=$(awk -v a="$best" -v b="$w" 'BEGIN { print (a == "" || b < a) ? b : a }')
      done
      json=$dir/summary.json
      if [ "$(value converged "$json")" != true ]; then
        echo "FAIL: $s P$p r$r $solver did not converge ($dir.log)"
        status=1
      fi
      if [ "${s%free}" = "$s" ] && [ "$(value contact_conditions_hold "$json")" != true ]; then
        echo "FAIL: $s P$p r$r $solver: the contact conditions do not hold"
        status=1
      fi
      wall=$best
      mb=$(awk '{ printf "%.0f", $1 / 1024 }' "$dir.mem")
      u=$(value max_displacement_mm "$json")
      e=$(value potential_energy_J "$json")
      if [ "$solver" = direct ]; then
        wall0=$wall mb0=$mb u0=$u e0=$e
      elif [ "${s%free}" != "$s" ]; then
        awk -v a="$u" -v b="$u0" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6 * b) }' || {
          echo "FAIL: $s P$p r$r: largest displacement $u mm with cg-amg, $u0 mm direct"
          status=1
        }
      fi
      # The inverse's solves: the direct inverse's Newton steps and
      # Jacobian products; the forward's: Newton steps and linear solves.
      if [ "${s%inverse}" != "$s" ]; then
        steps="$(value direct_inverse_newton_steps "$json") + $(value direct_inverse_jacobian_products "$json") products"
        solve=$(timer_seconds 'Direct inverse' "$dir.log")
      else
        steps=$(value newton_iterations "$json")
        solve=$(timer_seconds 'Linear solve' "$dir.log")
      fi
      awk -v se="$s" -v p="$p" -v r="$r" -v n="$(value n_dofs "$json")" -v so="$solver" -v w="$wall" \
        -v l="$solve" -v k="$steps" \
        -v u="$u" -v m="$mb" -v w0="$wall0" -v m0="$mb0" -v e="$e" -v e0="$e0" \
        'BEGIN { printf "| %s | %s | %s | %s | %s | %.2f | %s | %s | %.3f | %s | %.2f | %.2f | %.3g |\n", se, p, r, n, so, w, l, k, u, m, w / w0, m / m0, e - e0 }'
    done
  done
done
exit $status
