#!/bin/bash
# A scenario that fails does not end the run: tests/scenes/block_scenarios.prm
# (a block on a floor in a hydrostatic fluid; scenarios: Table 1's unnamed
# one, drained, unchanged) with the first crushed by 2000 m/s^2 onto the
# floor. The run must exit 4 (a scenario failed, the equilibrium
# converged), summary.json must say so scenario by scenario, and the two
# after it must give the shifts they give in a run without the failure
# (each starts from the equilibrium again).
#
# usage: run_scenarios_fail_alone.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
scene=tests/scenes/block_scenarios.prm
common=(--set "Output/Write VTU=false" --set "Solver/Maximum load step halvings=2")
"$exe" "${common[@]}" --set "Output/Directory=$out/failing" \
  --set "Scenario/Tissue body force=0, 0, -2000" "$scene" >"$out/failing.log" 2>"$out/failing.err"
code=$?
[ "$code" -eq 4 ] ||
  { echo "FAIL: exit code $code, not 4"; tail -n 20 "$out/failing.log"; cat "$out/failing.err"; exit 1; }
grep -q "1 of 3 scenarios did not converge (Scenario;" "$out/failing.err" ||
  { echo "FAIL: stderr does not name the failed scenario"; cat "$out/failing.err"; exit 1; }
"$exe" "${common[@]}" --set "Output/Directory=$out/passing" "$scene" >"$out/passing.log" 2>&1 ||
  { echo "FAIL: the run without the failure failed"; tail -n 20 "$out/passing.log"; exit 1; }
python3 - "$out/failing/summary.json" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1]))
want = {"converged": True, "scenarios_converged": False, "scenario_converged": False,
        "scenario_drained_converged": True, "scenario_unchanged_converged": True}
bad = {k: s.get(k) for k, v in want.items() if s.get(k) is not v}
if bad or not s.get("scenario_failure"):
    sys.exit(f"FAIL: summary.json has {bad}, failure {s.get('scenario_failure')!r}")
print("summary.json: the first scenario failed:", s["scenario_failure"][:100], "...")
PY
for name in drained unchanged; do
  numdiff -q -s ', \n' -a 1e-9 -r 1e-6 "$out/passing/scenario_$name.csv" "$out/failing/scenario_$name.csv" ||
    { echo "FAIL: scenario $name differs after the failed one"; exit 1; }
done
[ ! -e "$out/failing/scenario.csv" ] || { echo "FAIL: the failed scenario wrote its table"; exit 1; }
echo "ok: the first scenario failed alone; drained and unchanged as without it"
