#!/bin/bash
# Loads/Ventricular pressure on the Lame shell (tests/data/lame_shell.prm:
# meshes/shell_4mm.msh, whose cavity r < 10 mm is a closed inner surface),
# against linear elasticity's closed form (tests/check_lame_shell.py) and
# against the surface pressure confined to the inner layer:
# 1. 1 Pa in the cavity alone: the closed form with p_i = 1 Pa, p_o = 0
#    (P1 on 4 mm cells: 13.7 % RMS error of the radial displacement, the
#    cavity's displacement 0.868 of the exact one);
# 2. the same as Surface pressure = 1 Pa on Pressure labels = 1 (whose only
#    outer faces are the cavity's): the same displacements node by node;
# 3. 1 Pa in the cavity and Surface pressure = 0.5 Pa: the closed form with
#    p_o = 0.5 Pa (the outer pressure leaves the cavity walls alone;
#    16.2 %, 0.737; both pressures in the cavity would give 1.5 Pa there);
# 4. a scenario draining the ventricles (Scenario/Ventricular pressure =
#    0): the log names the change, and the stress-free model's largest
#    shift of label 1 is the largest displacement of case 1 (the change is
#    -1 Pa, linear at this load) within 1 %.
# usage: run_ventricles.sh RESTSHAPE OUTPUT_DIRECTORY
set -eu
exe=$1
out=$2
here=$(dirname "$0")
prm=$here/data/lame_shell.prm
check="/usr/bin/python3 $here/check_lame_shell.py --E 3000 --nu 0.3 --support 1e3"
rm -rf "$out"
mkdir -p "$out"
run() {
  local name=$1
  shift
  "$exe" --set "Output/Directory=$out/$name" "$@" "$prm" >"$out/$name.log" 2>&1 ||
    { echo "FAIL: $name: exit $?"; tail -n 3 "$out/$name.log"; exit 1; }
}
run inner
$check "$out/inner/nodes.csv" --p-inner 1 --tolerance 0.15 --cavity 0.85,0.89 \
  --label "ventricular pressure 1 Pa"
run layer --set "Loads/Ventricular pressure=" --set "Loads/Surface pressure=1" \
  --set "Loads/Pressure labels=1"
numdiff -q -r 1e-9 -a 1e-12 "$out/inner/nodes.csv" "$out/layer/nodes.csv" ||
  { echo "FAIL: the ventricular pressure differs from the surface pressure on label 1"; exit 1; }
echo "ok: ventricular pressure = surface pressure on the inner layer, node by node"
run both --set "Loads/Surface pressure=0.5"
$check "$out/both/nodes.csv" --p-inner 1 --p-outer 0.5 --tolerance 0.18 \
  --cavity 0.70,0.77 --label "1 Pa inside, 0.5 Pa outside"
run drained --set "Inverse problem/Enabled=true" --set "Scenario/Enabled=true" \
  --set "Scenario/Ventricular pressure=0"
grep -q "ventricular pressure 1 -> 0 Pa" "$out/drained.log" ||
  { echo "FAIL: the log does not name the scenario's change"; exit 1; }
/usr/bin/python3 - "$out/inner/nodes.csv" "$out/drained/scenario.csv" <<'PY'
import csv, math, sys
with open(sys.argv[1]) as f:
    largest = max(math.sqrt(sum(float(r[c]) ** 2 for c in ("u_x_mm", "u_y_mm", "u_z_mm")))
                  for r in csv.DictReader(f))
with open(sys.argv[2]) as f:
    shift = next(float(r["stress_free_max_mm"]) for r in csv.DictReader(f) if r["label"] == "1")
ratio = shift / largest
print(f"drained ventricles: largest shift of label 1 {shift:.6g} mm, of the "
      f"loaded shell {largest:.6g} mm, ratio {ratio:.4f} (in [0.99, 1.01])")
sys.exit(0 if 0.99 <= ratio <= 1.01 else 1)
PY
