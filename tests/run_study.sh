#!/bin/bash
# Study mode: restshape --study over element degree and refinement of the
# inverse column (exact rest shape known) runs every combination in its own
# folder and writes one table: 4 rows, all converged with the displacement
# formulation (the column's nu = 0 is below auto's 0.49), the exact rest-shape
# errors falling with refinement for both degrees, P2 at least 100 times as
# accurate as P1 on the same mesh, the direct inverse's Newton steps
# counted, each run's rest shape against the finest run's (P1 farther from
# it than P2 on the same mesh), a point per run in the plot, and one line
# per run started and finished. A study over Poisson's ratio on the Lame
# shell (tests/data/lame_shell.prm) names the formulation auto chose per
# row: displacement at 0.45, mixed at 0.4999. One over the formulation at
# nu = 0.4977 flags the displacement row's locking (locking_warning true,
# and its line says so), not the mixed one.
#
# usage: run_study.sh RESTSHAPE OUTPUT_DIRECTORY
set -eu
exe=$1
out=$2
rm -rf "$out"
"$exe" --study 'Discretization/Polynomial degree=1,2' \
  --study 'Mesh/Global refinements=0,1' --set "Output/Directory=$out" \
  prm/column_inverse.prm | tee "$out.log"
# A run that failed: its screen output.
grep -o 'FAILED .*; see [^)]*screen.log' "$out.log" | sed 's/.*; see //' | xargs -r tail -n 30
csv=$out/study/study.csv
[ -f "$out/study/study.txt" ] && [ -f "$out/study/study_error_vs_time.svg" ] ||
  { echo "FAIL: no study.txt or plot"; exit 1; }
[ -d "$out/study/04_Polynomial-degree-2_Global-refinements-1" ] ||
  { echo "FAIL: no folder per run"; exit 1; }
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { ++n; conv = conv && $col["converged"] == "true" && $col["formulation"] == "displacement"
    steps = steps && $col["direct_inverse_newton_steps"] > 0
    p = $col["Polynomial degree"]; r = $col["Global refinements"]
    e[p, r] = $col["rest_l2_error_relative"]; d[p, r] = $col["rest_shape_difference_to_finest"] }
  BEGIN { conv = 1; steps = 1 }
  END {
    ok = n == 4 && conv && steps && e[1,1] < e[1,0] && e[2,1] < e[2,0] && 100 * e[2,0] < e[1,0] &&
      d[2,1] == "reference" && d[2,0] < d[1,0] && d[1,1] < d[1,0]
    printf "rows %d, converged %d, direct inverse steps counted %d, L2: P1 %g -> %g, P2 %g -> %g; ", n, conv, steps, e[1,0], e[1,1], e[2,0], e[2,1]
    printf "rest shape vs finest: P1 %g -> %g, P2 %g\n", d[1,0], d[1,1], d[2,0]
    exit ok ? 0 : 1 }' "$csv" || { echo "FAIL: study table"; cat "$csv"; exit 1; }
[ "$(grep -c '<circle' "$out/study/study_error_vs_time.svg")" -eq 4 ] ||
  { echo "FAIL: not one point per run in the plot"; exit 1; }
[ "$(grep -c 'started: ' "$out.log")" -eq 4 ] && [ "$(grep -c 'finished: converged, .* DoFs' "$out.log")" -eq 4 ] ||
  { echo "FAIL: not one line per run started and finished"; exit 1; }
# column_pairs CSV A B: "a:b " for each row, from the columns named A, B.
column_pairs() {
  awk -F, -v a="$2" -v b="$3" 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    { printf "%s:%s ", $col[a], $col[b] }' "$1"
}
"$exe" --study "Materials/Poisson's ratio=0.45,0.4999" --set "Output/Directory=$out/nu" \
  --set "Solver/Check stability=false" tests/data/lame_shell.prm >"$out.nu.log" ||
  { echo "FAIL: the study over Poisson's ratio"; tail -n 5 "$out.nu.log"; exit 1; }
formulations=$(column_pairs "$out/nu/study/study.csv" "Poisson's ratio" formulation)
[ "$formulations" = "0.45:displacement 0.4999:mixed " ] ||
  { echo "FAIL: formulation column: $formulations"; exit 1; }
echo "formulation column: $formulations"
"$exe" --study "Discretization/Formulation=displacement,mixed" --set "Output/Directory=$out/locking" \
  --set "Materials/Poisson's ratio=0.4977" --set "Solver/Check stability=false" \
  tests/data/lame_shell.prm >"$out.locking.log" ||
  { echo "FAIL: the study over the formulation"; tail -n 5 "$out.locking.log"; exit 1; }
warned=$(column_pairs "$out/locking/study/study.csv" formulation locking_warning)
[ "$warned" = "displacement:true mixed:false " ] ||
  { echo "FAIL: locking_warning column: $warned"; exit 1; }
[ "$(grep -c 'finished: .*warned: the displacement formulation locks' "$out.locking.log")" -eq 1 ] ||
  { echo "FAIL: not one finished line warning of locking"; cat "$out.locking.log"; exit 1; }
echo "locking_warning column: $warned"
echo ok
