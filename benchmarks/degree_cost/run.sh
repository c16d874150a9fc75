#!/bin/bash
# Where the cost of degree 2 goes: one scene run at degree 1 and degree 2
# (same mesh, same law), the TimerOutput sections side by side, per call and
# as ratios P2 / P1, beside the ratio of the DoFs. Default: the brain with
# ventricles (prm/brain_ventricles.prm) with the Ogden law, the whole run
# (direct inverse, fixed point's check, stability check, scenarios), no VTU.
#
# usage: benchmarks/degree_cost/run.sh [--coarse] [PRM]
#   --coarse: prm/brain.prm's forward solve only (the version run in the
#   tests); fails when P2 needs more than twice P1's Newton steps (its cost
#   would then grow faster than its DoFs for a reason other than the cell
#   work).
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/degree_cost),
#   LAW (Ogden), REUSE (1: print the table of the runs already in OUT).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/degree_cost}
law=${LAW:-Ogden}
prm=prm/brain_ventricles.prm
extra=()
if [ "${1:-}" = --coarse ]; then
  shift
  prm=prm/brain.prm
  extra=(--set "Inverse problem/Enabled=false" --set "Scenario/Enabled=false")
fi
[ $# -gt 0 ] && prm=$1
if [ ${#extra[@]} -gt 0 ]; then
  # The scene's named scenarios need the inverse: off as well.
  for name in $(grep -oP '^subsection Scenario \K\S+' "$prm"); do
    extra+=(--set "Scenario $name/Enabled=false")
  done
fi
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

echo "machine: $(machine); scene: $prm; law: $law; extra: ${extra[*]:-none}"
status=0
for degree in 1 2; do
  dir=$out/p$degree
  [ "${REUSE:-0}" = 1 ] && [ -f "$dir/summary.json" ] && continue
  rm -rf "$dir"
  if ! "$exe" --set "Output/Directory=$dir" --set "Output/Write VTU=false" \
    --set "Discretization/Polynomial degree=$degree" \
    --set "Materials/Material law=$law" "${extra[@]}" "$prm" >"$dir.log" 2>&1; then
    echo "degree $degree failed: $(tail -n 1 "$dir.log")"
    exit 1
  fi
done
s1=$out/p1/summary.json s2=$out/p2/summary.json
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.1f", a / b; else print "-" }'; }
d1=$(value n_dofs "$s1") d2=$(value n_dofs "$s2")
# Newton steps of every solve (forward, fixed point, scenarios, stability's
# none): one linear solve each; the CG iterations they took.
n1=$(timer_calls "Linear solve" "$out/p1.log") n2=$(timer_calls "Linear solve" "$out/p2.log")
cg() { grep -o 'CG+AMG [0-9]* its' "$1" | awk '{ s += $2 } END { print s + 0 }'; }
i1=$(cg "$out/p1.log") i2=$(cg "$out/p2.log")
w1=$(value wall_seconds "$s1") w2=$(value wall_seconds "$s2")
echo
echo "| | P1 | P2 | P2 / P1 |"
echo "| --- | --- | --- | --- |"
echo "| DoFs | $d1 | $d2 | $(ratio "$d2" "$d1") |"
echo "| Newton steps, all solves | $n1 | $n2 | $(ratio "$n2" "$n1") |"
echo "| CG iterations, all solves | $i1 | $i2 | $(ratio "$i2" "$i1") |"
inverse() { grep -o 'Direct inverse: converged in [0-9]* Newton steps ([0-9]* factorisations, [0-9]* Jacobian products)' "$1" | sed 's/Direct inverse: converged in //'; }
[ -n "$(inverse "$out/p1.log")" ] &&
  echo "| direct inverse | $(inverse "$out/p1.log") | $(inverse "$out/p2.log") | |"
echo "| wall seconds | $w1 | $w2 | $(ratio "$w2" "$w1") |"
for section in Assembly "Linear solve" "AMG set-up" "Contact search" \
  "Direct inverse" Stability; do
  c1=$(timer_calls "$section" "$out/p1.log") c2=$(timer_calls "$section" "$out/p2.log")
  [ "$c1" = 0 ] && [ "$c2" = 0 ] && continue
  t1=$(timer_seconds "$section" "$out/p1.log") t2=$(timer_seconds "$section" "$out/p2.log")
  echo "| $section: seconds (calls) | $t1 ($c1) | $t2 ($c2) | $(ratio "$t2" "$t1"); per call $(ratio "$(awk -v t="$t2" -v c="$c2" 'BEGIN{print t/c}')" "$(awk -v t="$t1" -v c="$c1" 'BEGIN{print t/c}')") |"
done
if [ $((n2)) -gt $((2 * n1)) ]; then
  echo "FAILED: P2 took $n2 Newton steps, more than twice P1's $n1"
  status=1
fi
exit $status
