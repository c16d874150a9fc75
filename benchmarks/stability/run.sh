#!/bin/bash
# Stress test of numerical stability on the brain (prm/brain.prm, the whole
# inverse iteration): every combination of
#   Poisson's ratio          nu       in NU       (default 0.3 0.45 0.49 0.499)
#   stiffness contrast       E_tumour / E_brain in CONTRAST (1 10 100 1000)
#   gravity factor           g x      in GRAVITY  (1 5 10; times the buoyed weight)
#   polynomial degree        P        in DEGREES  (1 2)
# Each case must either converge or stop with a named diagnostic (exit code
# 2 and a "failure" in summary.json); a crash (exit 3 or a signal), a NaN or
# an infinity in summary.json, or a run longer than LIMIT seconds (default
# 1800; our limit, not the program's) is reported as a defect and makes the
# script exit 1. Prints a markdown table with the Newton and inverse
# iteration counts of every case and writes it to $OUT/stability.md.
#
# usage: benchmarks/stability/run.sh [--coarse]
#   --coarse: nu 0.3 and 0.499, contrast 1 and 1000, gravity 1, P1 (about
#             40 s): the version run in the tests.
# The column "sag" is the largest displacement of the stress-free model
# (inverse iteration 0): far smaller with P1 than with P2 at nu -> 0.5 is
# the signature of P1's volumetric locking.
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/stability),
# NU, CONTRAST, GRAVITY, DEGREES, LIMIT, SET (one extra
# 'Section/Parameter=value' for every case, e.g. 'Solver/Tangent shift=1e-3').
# Run from the repository root.
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/stability}
nus=${NU:-0.3 0.45 0.49 0.499}
contrasts=${CONTRAST:-1 10 100 1000}
gravities=${GRAVITY:-1 5 10}
degrees=${DEGREES:-1 2}
limit=${LIMIT:-1800}
if [ "${1:-}" = --coarse ]; then
  nus=${NU:-0.3 0.499}
  contrasts=${CONTRAST:-1 1000}
  gravities=${GRAVITY:-1}
  degrees=${DEGREES:-1}
fi
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

table=$out/stability.md
{
  echo "machine: $(machine)"
  echo
  echo "| nu | contrast | gravity x | P | result | sag (mm) | inverse iterations | Newton iterations | mean / max error (mm) | seconds | diagnostic |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
} >"$table"
cat "$table"
defects=0
for p in $degrees; do
  for nu in $nus; do
    for c in $contrasts; do
      for g in $gravities; do
        dir=$out/nu${nu}_c${c}_g${g}_p${p}
        rm -rf "$dir"
        e_tumour=$(awk -v c="$c" 'BEGIN { print 1500 * c }')
        gy=$(awk -v g="$g" 'BEGIN { print -9.81 * g }')
        start=$(date +%s.%N)
        timeout "$limit" "$exe" --set "Output/Directory=$dir" \
          --set "Materials/Poisson's ratio=$nu" \
          --set "Materials/Young's modulus=1:1500, 2:$e_tumour, 3:1500, 4:1500" \
          --set "Loads/Gravity=0, $gy, 0" \
          --set "Discretization/Polynomial degree=$p" \
          --set "Scenario/Enabled=false" \
          --set "Output/Write VTU=false" ${SET:+--set "$SET"} \
          prm/brain.prm >"$out/nu${nu}_c${c}_g${g}_p${p}.log" 2>&1
        code=$?
        seconds=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
        summary=$dir/summary.json
        result=converged
        diagnostic=""
        if [ $code -eq 124 ]; then
          result="DEFECT: over ${limit} s"
          defects=$((defects + 1))
        elif [ $code -eq 2 ]; then
          result="stopped"
          diagnostic=$(value failure "$summary" | cut -c1-140)
          [ -z "$diagnostic" ] && { result="DEFECT: exit 2 without a diagnostic"; defects=$((defects + 1)); }
        elif [ $code -ne 0 ]; then
          result="DEFECT: exit code $code"
          diagnostic=$(tail -n 1 "$out/nu${nu}_c${c}_g${g}_p${p}.log" | cut -c1-140)
          defects=$((defects + 1))
        fi
        if [ -f "$summary" ] && grep -qiE '(^|[^a-z])(nan|inf)([^a-z]|$)' "$summary"; then
          result="DEFECT: NaN or inf in summary.json"
          defects=$((defects + 1))
        fi
        its="-"; newton="-"; errors="-"; sag="-"
        [ -f "$dir/iterations.csv" ] && sag=$(awk -F, 'NR == 2 { printf "%.3g", $3 }' "$dir/iterations.csv")
        if [ -f "$summary" ]; then
          its=$(value inverse_iterations "$summary")
          newton=$(value newton_iterations "$summary")
          [ $code -eq 0 ] && errors=$(printf '%.3g / %.3g' "$(value mean_error_mm "$summary")" "$(value max_error_mm "$summary")")
        fi
        line="| $nu | $c | $g | $p | $result | $sag | ${its:--} | ${newton:--} | $errors | $seconds | $diagnostic |"
        echo "$line" | tee -a "$table"
      done
    done
  done
done
echo
echo "defects: $defects"
[ $defects -eq 0 ]
