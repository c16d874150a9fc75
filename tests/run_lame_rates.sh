#!/bin/bash
# Convergence under refinement on the Lame shell (tests/data/lame_shell.prm,
# 1 Pa in the cavity, meshes of 4, 2.8 and 2 mm made by meshes/make_shell.py):
# the RMS error of the radial displacement against the closed form
# (tests/check_lame_shell.py) and its rate against h = (volume / nodes)^(1/3).
# P2 (P2-P0): the rate of the mixed formulation at nu = 0.4999 and 0.49999
# must be that of the displacement formulation at nu = 0.3 (within 0.35)
# and at least 1.5; locking would show as a rate near 0. P1 (the averaged
# nodal pressure, boundary vertices interior, the default) on three
# meshes: its error at most that of the displacement element at nu = 0.3
# on every mesh, and its rate that one's within 0.35 (measured at 0.4999:
# 11.2, 7.3, 4.5 % against 13.7, 8.4, 5.3 %). The Bonet-Burton form
# (Nodal pressure at the boundary = own) fails this: 7.0 % on 2 mm.
# usage: run_lame_rates.sh RESTSHAPE OUTPUT_DIRECTORY
set -eu
exe=$1
out=$2
here=$(dirname "$0")
source "$here/lame_shell_runs.sh"
rm -rf "$out"
mkdir -p "$out"
sizes=(4 2.8 2)
for h in "${sizes[@]}"; do
  /usr/bin/python3 meshes/make_shell.py "$out/shell_$h.msh" 10 20 2 "$h"
done
# rms DEGREE H FORMULATION NU: "RMS_PERCENT NODES" of one run.
rms() {
  local name=p$1_$2_$3_$4
  "$exe" --set "Output/Directory=$out/$name" --set "Mesh/File=$out/shell_$2.msh" \
    --set "Discretization/Polynomial degree=$1" --set "Discretization/Formulation=$3" \
    --set "Materials/Poisson's ratio=$4" --set "Solver/Check stability=false" "$here/data/lame_shell.prm" >"$out/$name.log" 2>&1 ||
    { echo "FAIL: $name: exit $?" >&2; tail -n 3 "$out/$name.log" >&2; exit 1; }
  lame_figure "$name" "$4"
}
fail=0
# rates DEGREE FORMULATION NU SIZE...: prints the errors and rates, sets
# $last_rate to the finest pair's rate and $errors to the errors (%).
rates() {
  local degree=$1 formulation=$2 nu=$3 previous="" line=""
  shift 3
  errors=()
  for h in "$@"; do
    read -r e n < <(rms "$degree" "$h" "$formulation" "$nu")
    errors+=("$e")
    line+=" h=$h: $e % ($n nodes)"
    if [ -n "$previous" ]; then
      last_rate=$(lame_rate "$previous" "$e $n")
      line+=" rate $last_rate;"
    fi
    previous="$e $n"
  done
  echo "P$degree $formulation nu=$nu:$line" | tee -a "$out/rates.txt"
}
check() {
  local degree=$1 reference=$2
  shift 2
  for nu in 0.4999 0.49999; do
    rates "$degree" mixed "$nu" "$@"
    if awk -v r="$last_rate" -v r0="$reference" 'BEGIN { exit !(r >= 1.5 && r >= r0 - 0.35 && r <= r0 + 0.35) }'; then
      echo "ok: P$degree mixed at nu = $nu: rate $last_rate (displacement at 0.3: $reference)"
    else
      echo "FAIL: P$degree mixed at nu = $nu: rate $last_rate against $reference at nu = 0.3"
      fail=1
    fi
  done
}
rates 1 displacement 0.3 "${sizes[@]}"
reference=("${errors[@]}")
reference_rate=$last_rate
for nu in 0.4999 0.49999; do
  rates 1 mixed "$nu" "${sizes[@]}"
  for i in "${!errors[@]}"; do
    e=${errors[$i]} e0=${reference[$i]}
    if awk -v e="$e" -v e0="$e0" 'BEGIN { exit !(e <= e0) }'; then
      echo "ok: P1 mixed at nu = $nu, h = ${sizes[$i]}: $e % (displacement at 0.3: $e0 %)"
    else
      echo "FAIL: P1 mixed at nu = $nu, h = ${sizes[$i]}: $e % against $e0 % at 0.3"
      fail=1
    fi
  done
  if awk -v r="$last_rate" -v r0="$reference_rate" 'BEGIN { exit !(r >= r0 - 0.35 && r <= r0 + 0.35) }'; then
    echo "ok: P1 mixed at nu = $nu: rate $last_rate (displacement at 0.3: $reference_rate)"
  else
    echo "FAIL: P1 mixed at nu = $nu: rate $last_rate against $reference_rate at nu = 0.3"
    fail=1
  fi
done
rates 2 displacement 0.3 4 2.8
check 2 "$last_rate" 4 2.8
exit $fail
