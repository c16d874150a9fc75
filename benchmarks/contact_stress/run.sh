#!/bin/bash
# Stress matrix of the contact solve on the coarse brain, stress-free from
# the image (forward solves, no inverse): every combination of
#   skull    SKULLS   contact (0.5 mm out, prm/brain_skull_contact.prm),
#                     cut (0.5 mm into the brain, prm/brain_skull_cut.prm)
#   load     LOADS    buoyed gravity of G g (G in 0.25 0.5 1 2) along
#                     +-x, +-y, +-z ("1+x", "0.5-z", ...), and "full": the
#                     scene's gravity (-y) without buoyancy (strain 1.2)
#   degree   DEGREES  1 2
# with the CSF pressure off (its resultant on the open cerebrum would
# dominate these loads). Every case must converge with the strict contact
# conditions holding and no node beyond the skull, or stop (exit 2) with
# a named cause in summary.json. Anything else is a defect: a converged
# state with nodes outside or conditions that do not hold, a crash, NaN,
# exit 2 without a cause, a run over LIMIT seconds (our limit, not the
# program's). Each case is also solved without the skull (Contact/Obstacle
# file empty, the same loads and supports): the table gives both Newton
# step counts and their ratio, the cost of contact in Newton steps, and
# the last line the ratio of the sums over the converged cases. Prints a
# markdown table (Newton steps, load steps, active nodes, seconds) and
# writes it to $OUT/contact_stress.md with the Newton steps by what they
# follow (step_profile.py: active-set changes, releases, rounds of the
# strict check, convergence, halved attempts); exits 1 on a defect, or with
# --coarse if that ratio exceeds MAX_STEP_RATIO.
#
# usage: benchmarks/contact_stress/run.sh [--coarse]
#   --coarse: P1, both skulls, 1 and 2 g along +-x (8 cases, under a
#             minute): the version run in the tests (the full weight's
#             clean stop is test run/brain_full_weight_warned).
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/
# contact_stress), SKULLS, LOADS, DEGREES, LIMIT (600), SET (one extra
# 'Section/Parameter=value' for every case), MAX_STEP_RATIO (2.9; --coarse
# only: its 8 cases take 86 Newton steps against 36 without contact, 2.39,
# on the machine of doc/benchmarks.md, and 95 against 36, 2.64, with the
# same code on a 2-core AMD EPYC: the round-off of CG + AMG changes the
# active-set paths, and with the direct solver the same cases take 92
# against 32, 2.88; 109, 3.03, before nodes carried off the skull moved by
# a secant). Run from the repository root.
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/contact_stress}
skulls=${SKULLS:-contact cut}
all_loads=""
for g in 0.25 0.5 1 2; do
  for axis in +x -x +y -y +z -z; do all_loads="$all_loads $g$axis"; done
done
loads=${LOADS:-$all_loads full}
degrees=${DEGREES:-1 2}
limit=${LIMIT:-600}
max_step_ratio=${MAX_STEP_RATIO:-2.9}
coarse=false
if [ "${1:-}" = --coarse ]; then
  coarse=true
  loads=${LOADS:-1+x 1-x 2+x 2-x}
  degrees=${DEGREES:-1}
fi
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

# gravity LOAD: the Loads/Gravity vector of a load name (m/s^2).
gravity() {
  case "$1" in
  full) echo "0, -9.81, 0" ;;
  *)
    local g=${1%[+-]?} sign=${1: -2:1} axis=${1: -1}
    local v
    v=$(awk -v g="$g" -v s="$sign" 'BEGIN { printf "%.6g", (s == "-" ? -1 : 1) * 9.81 * g }')
    case $axis in
    x) echo "$v, 0, 0" ;;
    y) echo "0, $v, 0" ;;
    z) echo "0, 0, $v" ;;
    esac
    ;;
  esac
}

# solve DIR LOAD P SKULL [extra --set arguments]: one forward solve, its
# screen output in DIR.log; returns the program's exit code.
solve() {
  local dir=$1 load=$2 p=$3 skull=$4 fluid=1007
  shift 4
  [ "$load" = full ] && fluid=0
  rm -rf "$dir"
  timeout "$limit" "$exe" --set "Output/Directory=$dir" \
    --set "Inverse problem/Enabled=false" \
    --set "Scenario/Enabled=false" \
    --set "Loads/Surface pressure=0" \
    --set "Loads/Fluid density=$fluid" \
    --set "Loads/Gravity=$(gravity "$load")" \
    --set "Discretization/Polynomial degree=$p" \
    --set "Output/Write VTU=false" ${SET:+--set "$SET"} "$@" \
    "prm/brain_skull_$skull.prm" >"$dir.log" 2>&1
}

table=$out/contact_stress.md
{
  echo "machine: $(machine)"
  echo
  echo "| skull | load | P | result | Newton steps | without contact | ratio | load steps | active nodes | nodes outside | seconds | cause |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
} >"$table"
cat "$table"
defects=0
declare -A logs # the cases' logs by degree, for step_profile.py
sum_with=0
sum_without=0
for p in $degrees; do
  for skull in $skulls; do
    for load in $loads; do
      name=${skull}_${load}_p$p
      dir=$out/$name
      logs[$p]+=" $dir.log"
      start=$(date +%s.%N)
      solve "$dir" "$load" "$p" "$skull"
      code=$?
      seconds=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
      summary=$dir/summary.json
      result=converged
      cause=""
      if [ $code -eq 124 ]; then
        result="DEFECT: over ${limit} s"
      elif [ $code -eq 2 ]; then
        result=stopped
        cause=$(text_value failure "$summary")
        [ -z "$cause" ] && result="DEFECT: exit 2 without a cause"
      elif [ $code -ne 0 ]; then
        result="DEFECT: exit code $code"
        cause=$(tail -n 1 "$dir.log" | cut -c1-160)
      fi
      if [ -f "$summary" ] && grep -qiE '(^|[^a-z])(nan|inf)([^a-z]|$)' "$summary"; then
        result="DEFECT: NaN or inf in summary.json"
      fi
      newton=-; steps=-; active=-; outside=-
      if [ -f "$summary" ]; then
        newton=$(value newton_iterations "$summary")
        steps=$(value load_steps "$summary")
        active=$(value active_contact_nodes "$summary")
        outside=$(value nodes_outside "$summary")
        if [ $code -eq 0 ] && { [ "${outside:-1}" != 0 ] ||
          [ "$(value contact_conditions_hold "$summary")" != true ]; }; then
          result="DEFECT: converged with the contact conditions violated"
        fi
      fi
      # The same solve without the skull.
      without=-; ratio=-
      if [ "$result" = converged ] &&
        solve "$dir.free" "$load" "$p" "$skull" --set "Contact/Obstacle file="; then
        without=$(value newton_iterations "$dir.free/summary.json")
        ratio=$(awk -v a="$newton" -v b="$without" 'BEGIN { printf "%.1f", a / b }')
        sum_with=$((sum_with + newton))
        sum_without=$((sum_without + without))
      fi
      case $result in DEFECT*) defects=$((defects + 1)) ;; esac
      echo "| $skull | $load | $p | $result | ${newton:--} | $without | $ratio | ${steps:--} | ${active:--} | ${outside:--} | $seconds | $cause |" | tee -a "$table"
    done
  done
done
echo
echo "defects: $defects"
[ $defects -eq 0 ] || exit 1
[ $sum_without -gt 0 ] || exit 0
ratio=$(awk -v a=$sum_with -v b=$sum_without 'BEGIN { printf "%.2f", a / b }')
echo "Newton steps with / without contact, converged cases: $sum_with / $sum_without = $ratio" |
  tee -a "$table"
# Where the steps go, by what each step follows (step_profile.py).
for p in $degrees; do
  echo
  echo "P$p Newton steps by what they follow:"
  # shellcheck disable=SC2086 # one log path per word
  python3 "$(dirname "$0")/step_profile.py" ${logs[$p]}
done | tee -a "$table"
if $coarse && awk -v r="$ratio" -v m="$max_step_ratio" 'BEGIN { exit !(r > m) }'; then
  echo "contact costs more than $max_step_ratio times the Newton steps of the solves without it"
  exit 1
fi
