#!/bin/bash
# Benchmark: wall time against error, per discretisation, on the inverse
# gravity column (prm/column_inverse.prm: its exact rest shape is known, so
# the error is exact). Elements: P1 and P2 tetrahedra, Q1 and Q2 hexahedra
# (each tetrahedron split into four hexahedra), each under uniform
# refinement (Mesh/Global refinements = 0, 1, ...; every level a separate
# run, so the time is that of one whole inverse solve, setup and output
# included, VTU output off). Writes $OUT/time_vs_error.csv
# (element, level, n_cells, n_dofs, seconds, rest L2 and H1 error relative,
# inverse iterations) and prints a markdown table; plot with
# benchmarks/time_vs_error/plot.py.
#
# usage: benchmarks/time_vs_error/run.sh [--coarse]
#   --coarse: level 0 of every element only (the version run in the tests)
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/time_vs_error),
# LEVELS_P1 (0 1 2 3), LEVELS_P2 (0 1 2), LEVELS_Q1 (0 1 2), LEVELS_Q2 (0 1).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/time_vs_error}
scene=prm/column_inverse.prm
declare -A levels=([P1]=${LEVELS_P1:-0 1 2 3} [P2]=${LEVELS_P2:-0 1 2}
                   [Q1]=${LEVELS_Q1:-0 1 2} [Q2]=${LEVELS_Q2:-0 1})
if [ "${1:-}" = --coarse ]; then
  levels=([P1]=0 [P2]=0 [Q1]=0 [Q2]=0)
fi
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

csv=$out/time_vs_error.csv
echo "scene: $scene; machine: $(machine)"
start_table "$csv" element,level,n_cells,n_dofs,seconds,rest_l2_error_relative,rest_h1_error_relative,inverse_iterations \
  element level cells DoFs seconds "rest L2 error (rel.)" "rest H1 error (rel.)" "inverse iterations"
status=0
for element in P1 P2 Q1 Q2; do
  case $element in
  P*) cells=tetrahedra ;;
  Q*) cells=hexahedra ;;
  esac
  degree=${element:1:1}
  for level in ${levels[$element]}; do
    dir=$out/${element}_$level
    if ! "$exe" --set "Output/Directory=$dir" --set "Output/Write VTU=false" \
      --set "Mesh/Cell type=$cells" --set "Discretization/Polynomial degree=$degree" \
      --set "Mesh/Global refinements=$level" --set "Inverse problem/Tolerance=1e-9" \
      "$scene" >"$dir.log" 2>&1; then
      echo "| $element | $level | failed: $(tail -n 1 "$dir.log") |"
      status=1
      continue
    fi
    s=$dir/summary.json
    row="$element,$level,$(value n_cells "$s"),$(value n_dofs "$s"),$(value wall_seconds "$s"),$(value rest_l2_error_relative "$s"),$(value rest_h1_error_relative "$s"),$(value inverse_iterations "$s")"
    echo "$row" >>"$csv"
    echo "| ${row//,/ | } |"
  done
done
# The figure the coarse version asserts: on the same mesh (level 0) the
# quadratic elements are at least 100 times as accurate in L2 as the linear
# ones (measured: P2/P1 about 1/1900, Q2/Q1 about 1/14000).
awk -F, '$2 == 0 { e[$1] = $6 }
  END { ok = 1
        if (("P1" in e) && ("P2" in e)) { printf "P2/P1 L2 error at level 0: %.3g\n", e["P2"] / e["P1"]; ok = ok && e["P2"] * 100 < e["P1"] }
        if (("Q1" in e) && ("Q2" in e)) { printf "Q2/Q1 L2 error at level 0: %.3g\n", e["Q2"] / e["Q1"]; ok = ok && e["Q2"] * 100 < e["Q1"] }
        exit !ok }' "$csv" || { echo "FAIL: a quadratic element is not 100 times as accurate as its linear one"; status=1; }
exit $status
