#!/bin/bash
# Benchmark: the error estimators against the exact error, on the gravity
# column (tests/scenes/column_q1_convergence.prm, Q1 hexahedra, and
# column_p1_convergence.prm, P1 tetrahedra; exact solution known): for each
# Adaptive refinement/Estimator (kelly, traction jump) and strategy (global;
# adaptive, 30 % of the cells per cycle, Q1 only) the estimate, the exact
# relative H1 error, their ratio (the effectivity) and the wall time of
# every cycle. A good estimator keeps the ratio near 1 under refinement and
# drives adaptive meshes at least as accurate as global ones for their DoFs.
# Writes $OUT/estimators.csv and prints a markdown table.
#
# usage: benchmarks/time_vs_error/estimators.sh [--coarse]
#   --coarse: one refinement cycle (the version run in the tests)
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/time_vs_error),
# CYCLES (3).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/time_vs_error}
cycles=${CYCLES:-3}
[ "${1:-}" = --coarse ] && cycles=1
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

csv=$out/estimators.csv
echo "scene: the gravity column; machine: $(machine)"
start_table "$csv" element,strategy,estimator,cycle,n_dofs,estimated_error,h1_error_relative,effectivity,seconds \
  element strategy estimator cycle DoFs estimate "exact H1 error" "estimate / exact" seconds
status=0
for element in Q1 P1; do
  scene=tests/scenes/column_${element,,}_convergence.prm
  strategies="global adaptive"
  [ "$element" = P1 ] && strategies=global # no hanging nodes on tetrahedra
  for strategy in $strategies; do
    for estimator in kelly "traction jump"; do
      dir=$out/estimators_${element}_${strategy}_${estimator// /_}
      rm -rf "$dir"
      if ! "$exe" --set "Output/Directory=$dir" --set "Output/Write VTU=false" \
        --set "Adaptive refinement/Cycles=$cycles" --set "Adaptive refinement/Strategy=$strategy" \
        --set "Adaptive refinement/Estimator=$estimator" "$scene" >"$dir.log" 2>&1; then
        echo "FAILED: $element $strategy $estimator (see $dir.log)"
        status=1
        continue
      fi
      # convergence.csv: cycle,n_cells,n_dofs,estimated_error,...,h1_error_relative,...,wall_seconds
      awk -F, -v e="$element" -v s="$strategy" -v est="$estimator" -v csv="$csv" '
        NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
        { eta = $col["estimated_error"]; h1 = $col["h1_error_relative"]
          if (!(h1 > 0) || !(eta > 0)) { bad = 1 }
          ratio = h1 > 0 ? eta / h1 : 0
          printf "%s,%s,%s,%d,%d,%.6g,%.6g,%.4g,%.3f\n", e, s, est, $col["cycle"], $col["n_dofs"], eta, h1, ratio, $col["wall_seconds"] >> csv
          printf "| %s | %s | %s | %d | %d | %.3g | %.3g | %.2f | %.2f |\n", e, s, est, $col["cycle"], $col["n_dofs"], eta, h1, ratio, $col["wall_seconds"] }
        END { exit bad }' "$dir/convergence.csv" || {
        echo "FAILED: $element $strategy $estimator: an estimate or exact error is not positive"
        status=1
      }
    done
  done
done
# The traction jump is an estimate to within a factor 2 of the exact error
# in every cycle (Kelly's may overestimate more: it is not checked).
awk -F, 'NR > 1 && $3 == "traction jump" && ($8 < 0.5 || $8 > 2) {
    bad = 1; print "FAILED: traction jump effectivity " $8 " (" $1 " " $2 " cycle " $4 ")" }
  END { exit bad }' "$csv" || status=1
exit $status
