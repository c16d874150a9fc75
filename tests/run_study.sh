#!/bin/bash
# Study mode: restshape --study over element degree and refinement of the
# inverse column (exact rest shape known) runs every combination in its own
# folder and writes one table: 4 rows, all converged, the exact rest-shape
# errors falling with refinement for both degrees, P2 at least 100 times as
# accurate as P1 on the same mesh, and the plot.
#
# usage: run_study.sh RESTSHAPE OUTPUT_DIRECTORY
set -eu
exe=$1
out=$2
rm -rf "$out"
"$exe" --study 'Discretization/Polynomial degree=1,2' \
  --study 'Mesh/Global refinements=0,1' --set "Output/Directory=$out" \
  prm/column_inverse.prm | tee "$out.log"
csv=$out/study/study.csv
[ -f "$out/study/study.txt" ] && [ -f "$out/study/study_error_vs_time.svg" ] ||
  { echo "FAIL: no study.txt or plot"; exit 1; }
[ -d "$out/study/04_Polynomial-degree-2_Global-refinements-1" ] ||
  { echo "FAIL: no folder per run"; exit 1; }
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { ++n; conv = conv && $col["converged"] == "true"
    e[$col["Polynomial degree"], $col["Global refinements"]] = $col["rest_l2_error_relative"] }
  BEGIN { conv = 1 }
  END {
    ok = n == 4 && conv && e[1,1] < e[1,0] && e[2,1] < e[2,0] && 100 * e[2,0] < e[1,0]
    printf "rows %d, converged %d, L2: P1 %g -> %g, P2 %g -> %g\n", n, conv, e[1,0], e[1,1], e[2,0], e[2,1]
    exit ok ? 0 : 1 }' "$csv" || { echo "FAIL: study table"; cat "$csv"; exit 1; }
echo ok
