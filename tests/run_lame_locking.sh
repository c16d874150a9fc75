#!/bin/bash
# Locking on the Lame shell (tests/data/lame_shell.prm, 4 mm cells, 1 Pa in
# the cavity, tests/check_lame_shell.py): P2 tetrahedra with the
# displacement formulation at nu = 0.3 set the accuracy the element has
# on this mesh; at nu = 0.4999 and 0.49999 the mixed formulation
# (Discretization/Formulation = mixed, P2-P0) must reach it within 10 %
# of the RMS error, and its cavity within 2 % of the exact displacement
# ratio of nu = 0.3; Formulation = auto chooses mixed there (summary.json)
# and gives the same nodes; the displacement formulation at 0.4999 warns;
# the pressure_Pa cell field (VTK's reader) has the exact mean pressure;
# P1 mixed at 0.4999 as accurate as P1 at 0.3, its pressure field
# smooth; its Bonet-Burton form (own) notes that its error stops falling.
# usage: run_lame_locking.sh RESTSHAPE OUTPUT_DIRECTORY
set -eu
exe=$1
out=$2
here=$(dirname "$0")
prm=$here/data/lame_shell.prm
rm -rf "$out"
mkdir -p "$out"
run() {
  local name=$1 nu=$2
  shift 2
  "$exe" --set "Output/Directory=$out/$name" --set "Discretization/Polynomial degree=2" \
    --set "Materials/Poisson's ratio=$nu" --set "Solver/Check stability=false" \
    "$@" "$prm" >"$out/$name.log" 2>&1 ||
    { echo "FAIL: $name: exit $?"; tail -n 3 "$out/$name.log"; exit 1; }
}
# figures NAME NU: "RMS CAVITY" of the run against the closed form.
figures() {
  /usr/bin/python3 "$here/check_lame_shell.py" "$out/$1/nodes.csv" --E 3000 \
    --nu "$2" --p-inner 1 --support 1e3 --label "$1" | tee -a "$out/figures.txt" |
    sed -E 's/.*displacement ([0-9.]+) %.*exact ([0-9.]+).*/\1 \2/'
}
run displacement_0.3 0.3 --set Discretization/Formulation=displacement
read -r rms_ref cavity_ref < <(figures displacement_0.3 0.3)
run displacement_0.4999 0.4999 --set Discretization/Formulation=displacement
figures displacement_0.4999 0.4999 >/dev/null
grep -q "Warning: Poisson's ratio 0.4999 (0.49 or above) with the displacement formulation" \
  "$out/displacement_0.4999.log" || { echo "FAIL: no locking warning"; exit 1; }
fail=0
for nu in 0.4999 0.49999; do
  run mixed_$nu $nu --set Discretization/Formulation=mixed --set "Output/Write VTU=$([ $nu = 0.4999 ] && echo true || echo false)"
  read -r rms cavity < <(figures mixed_$nu $nu)
  if awk -v r="$rms" -v r0="$rms_ref" -v c="$cavity" -v c0="$cavity_ref" \
    'BEGIN { exit !(r <= 1.1 * r0 && c >= c0 - 0.02 && c <= c0 + 0.02) }'; then
    echo "ok: mixed at nu = $nu: RMS $rms % (P2 at 0.3: $rms_ref %), cavity $cavity ($cavity_ref)"
  else
    echo "FAIL: mixed at nu = $nu: RMS $rms % against $rms_ref % at 0.3, cavity $cavity against $cavity_ref"
    fail=1
  fi
done
# field NAME [OPTION...]: tests/check_pressure_field.py on the run at 0.4999
# (by default: mean within 10 %, scatter and jump under half the exact
# pressure; exit 0 when it holds).
field() {
  local line status=0
  line=$(/usr/bin/python3 "$here/check_pressure_field.py" "$out/$1" --E 3000 --nu 0.4999 \
    --p-inner 1 --support 1e3 --label "$1" "${@:2}") || status=$?
  echo "$line" | tee -a "$out/figures.txt"
  return $status
}
# The pressure field as ParaView's VTK reads it: the cells' mean of
# pressure_Pa against the exact -tr(sigma)/3 = -3 K A (constant in the
# Lame shell), within 10 % (P2-P0: 4 %; single cells scatter about it).
field mixed_0.4999 --scatter inf --jump inf --volume-change 1e-5 || fail=1
run auto_0.4999 0.4999
grep -q '"formulation": "mixed"' "$out/auto_0.4999/summary.json" ||
  { echo "FAIL: auto did not choose mixed at 0.4999"; exit 1; }
numdiff -q -r 1e-9 -a 1e-12 "$out/mixed_0.4999/nodes.csv" "$out/auto_0.4999/nodes.csv" ||
  { echo "FAIL: auto differs from mixed"; exit 1; }
echo "ok: auto chooses mixed at 0.4999"
# Linear tetrahedra: the averaged nodal pressure (mixed on P1; boundary
# vertices: interior, the default) at 0.4999 at least as accurate as P1
# with displacements at 0.3 (measured 11.2 % against 13.7 %, cavity 0.93
# against 0.87), with no note; its pressure field free of checkerboards
# (tests/check_pressure_field.py: the cells' mean within 10 % of the
# exact pressure, the cells' scatter about it and the jump across faces
# under half of it). The Bonet-Burton form (own) notes that its error
# stops falling under refinement, and its field fails the same check
# (scatter 1.1 times the pressure): the check can fail.
run p1_displacement_0.3 0.3 --set Discretization/Formulation=displacement \
  --set "Discretization/Polynomial degree=1"
read -r rms_p1 _ < <(figures p1_displacement_0.3 0.3)
p1_mixed() { # NAME [--set ...]: P1 mixed at 0.4999 with its VTU
  run "$1" 0.4999 --set Discretization/Formulation=mixed \
    --set "Discretization/Polynomial degree=1" --set "Output/Write VTU=true" "${@:2}"
}
p1_mixed p1_mixed_0.4999
read -r rms cavity < <(figures p1_mixed_0.4999 0.4999)
grep -q "averaged nodal pressure of linear tetrahedra (boundary vertices: interior)" \
  "$out/p1_mixed_0.4999.log" || { echo "FAIL: P1 mixed does not name its element"; exit 1; }
grep -q '"nodal_pressure_boundary": "interior"' "$out/p1_mixed_0.4999/summary.json" ||
  { echo "FAIL: summary.json of P1 mixed without nodal_pressure_boundary"; exit 1; }
! grep -q "^Note:" "$out/p1_mixed_0.4999.log" ||
  { echo "FAIL: P1 mixed (interior) has a note"; exit 1; }
if awk -v r="$rms" -v r0="$rms_p1" -v c="$cavity" \
  'BEGIN { exit !(r <= r0 && c >= 0.85) }'; then
  echo "ok: P1 mixed at nu = 0.4999: RMS $rms % (P1 at 0.3: $rms_p1 %), cavity $cavity"
else
  echo "FAIL: P1 mixed at nu = 0.4999: RMS $rms % against $rms_p1 % at 0.3, cavity $cavity"
  fail=1
fi
field p1_mixed_0.4999 || { echo "FAIL: P1 mixed's pressure field"; fail=1; }
p1_mixed p1_own_0.4999 --set "Discretization/Nodal pressure at the boundary=own"
grep -q "^Note: at Poisson's ratio 0.4999 (0.495 or above) the averaged nodal pressure's error stops" \
  "$out/p1_own_0.4999.log" || { echo "FAIL: P1 mixed (own) at 0.4999 without its note"; exit 1; }
grep -q '"formulation_note": "at Poisson' "$out/p1_own_0.4999/summary.json" ||
  { echo "FAIL: summary.json of P1 mixed (own) at 0.4999 without formulation_note"; exit 1; }
! grep -q '"formulation_note"' "$out/mixed_0.4999/summary.json" ||
  { echo "FAIL: P2-P0's summary.json has a formulation_note"; exit 1; }
! grep -q "^Note: .*averaged nodal pressure" "$out/mixed_0.4999.log" ||
  { echo "FAIL: P2-P0 has the averaged nodal pressure's note"; exit 1; }
if field p1_own_0.4999; then
  echo "FAIL: the pressure field check passes the own form's scattered field"
  fail=1
else
  echo "ok: the pressure field check fails on the own form's field"
fi
cat "$out/figures.txt"
exit $fail
