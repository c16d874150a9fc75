#!/bin/bash
# The inverse iteration when a forward solve fails (source/inverse_problem.cc):
# the soft cantilever of prm/cantilever.prm at E = 40 kPa, P1, whose target
# needs a rest shape beyond the fixed point's reach. Expected: some plain
# updates are taken in part (the forward solve reached equilibrium part of
# the way), then a forward solve fails for even the smallest fraction of its
# update and the iteration stops at once, without shortening the update
# again: exit code 2, one line on stderr naming the cause, summary.json with
# "converged": false and no NaN, no rest_shape.msh, and exactly one failed
# forward solve beyond the accepted iterations and rejected Anderson steps.
# At E = 50 kPa three partial updates in a row gain nothing: the iteration
# stops as stalled at the third. These two runs turn the Newton watchdog
# off (Solver/Watchdog steps = 0): with it, their forward solves reach
# further and the iteration stops as diverged instead (29 to 84 mm at
# 40 kPa), a path other tests cover.
# Then a forward solve that gives up (2 Newton steps, no load halvings) with
# the adaptive tangent: its one stderr line suggests Solver/Tangent shift,
# and does not once the shift is set. Last, a load no equilibrium can carry
# (the cantilever pushed into its support at 10^5 g, no load halvings, 200
# Newton steps allowed) with the shift: every step is cut short by inverted
# cells, so the shift is raised; at its largest value (1e4) Newton stops
# with a message saying so and naming an inverted cell, within 20 steps
# (before the cap on the shift, it raised the shift to 1e19 and ran all 200).
# Without the shift the same load fails in the line search, whose message
# names the inverted cells and does not suggest the shift.
#
# usage: run_inverse_gives_up.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
"$exe" --set "Output/Directory=$out" --set "Discretization/Polynomial degree=1" \
  --set "Materials/Young's modulus=40000" --set "Solver/Maximum Newton iterations=25" \
  --set "Inverse problem/Enabled=true" --set "Output/Write VTU=false" --set "Solver/Watchdog steps=0" \
  prm/cantilever.prm >"$out.stdout" 2>"$out.stderr"
code=$?
fail() { echo "FAIL: $1"; echo "--- exit code $code; stderr:"; cat "$out.stderr"; exit 1; }
[ "$code" -eq 2 ] || fail "exit code $code, expected 2"
[ "$(wc -l <"$out.stderr")" -eq 1 ] || fail "expected exactly one line on stderr"
grep -q "did not converge even for the smallest fraction of the update" "$out.stderr" ||
  fail "stderr does not name the failed forward solve"
grep -q "that shorter update is taken" "$out.stdout" || fail "no partial update was taken"
s=$out/summary.json
grep -q '"converged": false' "$s" || fail "summary.json does not say converged: false"
grep -qiE 'nan|inf' "$s" && fail "NaN or infinity in summary.json"
[ ! -e "$out/rest_shape.msh" ] || fail "rest_shape.msh written for an unconverged iteration"
n() { grep "\"$1\"" "$s" | sed 's/[^0-9]//g'; }
solves=$(n forward_solves)
expected=$(($(n inverse_iterations) + $(n rejected_anderson_steps) + 2))
echo "forward solves $solves; iteration 0 + accepted + rejected Anderson + 1 failed = $expected"
[ "$solves" -eq "$expected" ] || fail "the failed update was retried"
echo "ok: $(cat "$out.stderr")"

# At E = 50 kPa the forward solves of three updates in a row stop part of
# the way without the error improving on its best: the iteration stops
# there ("stalled"), not after 10 iterations without gain.
"$exe" --set "Output/Directory=$out/stalled" --set "Discretization/Polynomial degree=1" \
  --set "Materials/Young's modulus=50000" --set "Solver/Maximum Newton iterations=25" \
  --set "Inverse problem/Enabled=true" --set "Output/Write VTU=false" --set "Solver/Watchdog steps=0" \
  prm/cantilever.prm >"$out.stalled.stdout" 2>"$out.stderr"
code=$?
[ "$code" -eq 2 ] || fail "stalled: exit code $code, expected 2"
[ "$(wc -l <"$out.stderr")" -eq 1 ] || fail "stalled: expected exactly one line on stderr"
grep -qF "stalled: the forward solves of the last 3 updates reached equilibrium only part of the way" \
  "$out.stderr" || fail "stalled: stderr does not name the run of partial updates"
partial=$(grep -c "that shorter update is taken" "$out.stalled.stdout")
[ "$partial" -eq 3 ] || fail "stalled: $partial partial updates, expected the stop at the third"
grep -qiE 'nan|inf' "$out/stalled/summary.json" && fail "stalled: NaN or infinity in summary.json"
echo "ok: $(cat "$out.stderr")"

hint="Solver/Tangent shift = 1e-3 may help"
# forward NAME SHIFT [--set ...]: a forward solve of the cantilever with the
# adaptive tangent and no load halvings, expected to fail (exit code 2, one
# line on stderr, written to $out.stderr).
forward() {
  local name=$1 shift=$2
  shift 2
  "$exe" --set "Output/Directory=$out/$name" --set "Discretization/Tangent=adaptive" \
    --set "Solver/Tangent shift=$shift" --set "Solver/Maximum load step halvings=0" \
    --set "Output/Write VTU=false" "$@" prm/cantilever.prm >"$out.$name.stdout" 2>"$out.stderr"
  code=$?
  [ "$code" -eq 2 ] || fail "$name: exit code $code, expected 2"
  [ "$(wc -l <"$out.stderr")" -eq 1 ] || fail "$name: expected one line on stderr"
}
for shift in 0 1e-3; do
  forward "forward_$shift" "$shift" --set "Solver/Maximum Newton iterations=2"
  if [ "$shift" = 0 ]; then
    grep -qF "$hint" "$out.stderr" || fail "no shift: the message does not suggest the tangent shift"
  else
    grep -qF "$hint" "$out.stderr" && fail "shift set: the message still suggests it"
  fi
done
echo "ok: the forward solve's message suggests the tangent shift only when it is off"

# The cantilever pushed into its support at 10^5 g, in one increment.
crush=(--set "Discretization/Polynomial degree=1" --set "Solver/Maximum Newton iterations=200"
  --set "Solver/Initial load steps=1" --set "Loads/Gravity=-981000, 0, 0")
forward stall 1e-3 "${crush[@]}"
grep -qF "the largest shift tried" "$out.stderr" || fail "stalled Newton: the message does not name the shift"
grep -qF "inverted (det F <= 0), e.g. label" "$out.stderr" ||
  fail "stalled Newton: the message does not name the inverted cells"
steps=$(grep '"newton_iterations"' "$out/stall/summary.json" | sed 's/[^0-9]//g')
echo "stalled Newton: stopped after $steps steps: $(cat "$out.stderr")"
[ "$steps" -le 20 ] || fail "stalled Newton ran $steps steps, expected at most 20"
grep -qiE 'nan|inf' "$out/stall/summary.json" && fail "NaN or infinity in summary.json"
echo "ok: a stalled Newton with the shift stops at the largest shift"

forward stall0 0 "${crush[@]}"
grep -qF "trial steps inverted cells" "$out.stderr" || fail "inverted cells, no shift: the message does not name them"
grep -qF "$hint" "$out.stderr" && fail "inverted cells, no shift: the message suggests the shift"
echo "ok: $(cat "$out.stderr")"
