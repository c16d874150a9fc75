#!/bin/bash
# prm/brain_in_vivo.prm (doc/brain.md, section 8), the whole scene: auto
# chooses the mixed formulation (the averaged nodal pressure, boundary
# vertices interior) at nu = 0.4977, the rest shape converges, every
# scenario converges (exit 0), and the tumour's pre-stressed shift in each
# scenario (scenario*.csv) is the one doc/brain.md gives, to TOLERANCE
# (1 %); no note (the element converges at this nu). The forward solve
# from the image with P2-P0 converges with the contact conditions holding
# and sags more than P1 mixed's: its mean displacement at least
# MIN_P2_RATIO (1.05) times P1's (1.401 against 1.276 mm, doc/brain.md).
# On 2 MPI ranks Table 1 gives the tumour shift of 1 rank.
# usage: run_brain_in_vivo.sh RESTSHAPE OUTPUT_DIRECTORY
set -eu -o pipefail
exe=$1
out=$2
tolerance=${TOLERANCE:-0.01}
min_p2_ratio=${MIN_P2_RATIO:-1.05}
rm -rf "$out"
mkdir -p "$out"
"$exe" --set "Output/Directory=$out/run" --set "Output/Write VTU=false" \
  prm/brain_in_vivo.prm >"$out/screen.log" 2>&1 ||
  { echo "FAIL: exit $?"; tail -n 5 "$out/screen.log"; exit 1; }
grep -q "Formulation: mixed, the averaged nodal pressure of linear tetrahedra (boundary vertices: interior)" \
  "$out/screen.log" || { echo "FAIL: not the mixed formulation"; exit 1; }
grep -q '"formulation": "mixed"' "$out/run/summary.json" || { echo "FAIL: summary.json"; exit 1; }
! grep -q "^Note:" "$out/screen.log" || { echo "FAIL: a note on the element"; exit 1; }
fail=0
# scenario file: the tumour's pre-stressed centroid shift (mm) in doc/brain.md
for expected in scenario:4.712 scenario_prone:3.010 scenario_drained:7.844 \
  scenario_craniotomy:6.736; do
  IFS=: read -r name shift <<<"$expected"
  got=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    $1 == "tumour" { print $c["prestressed_centroid_mm"] }' "$out/run/$name.csv")
  if awk -v g="$got" -v e="$shift" -v t="$tolerance" 'BEGIN { d = g - e; exit !(d < 0 ? -d <= t * e : d <= t * e) }'; then
    echo "ok: $name: tumour shift $got mm (doc/brain.md: $shift mm)"
  else
    echo "FAIL: $name: tumour shift $got mm, doc/brain.md gives $shift mm"
    fail=1
  fi
done
# forward DEGREE: the mean displacement (mm) of the forward solve from the
# image, no inverse and no scenario.
forward() {
  "$exe" --set "Output/Directory=$out/forward_p$1" --set "Discretization/Polynomial degree=$1" \
    --set "Inverse problem/Enabled=false" --set "Scenario/Enabled=false" \
    --set "Scenario prone/Enabled=false" --set "Scenario drained/Enabled=false" \
    --set "Scenario craniotomy/Enabled=false" --set "Output/Write VTU=false" \
    --set "Solver/Check stability=false" prm/brain_in_vivo.prm >"$out/forward_p$1.log" 2>&1 ||
    { echo "FAIL: forward P$1: exit $?" >&2; tail -n 3 "$out/forward_p$1.log" >&2; return 1; }
  grep -q "the contact conditions hold" "$out/forward_p$1.log" ||
    { echo "FAIL: forward P$1: the contact conditions" >&2; return 1; }
  sed -n 's/^  Displacement: max [0-9.e+-]* mm, mean \([0-9.e+-]*\) mm.*/\1/p' "$out/forward_p$1.log"
}
p1=$(forward 1) || exit 1
p2=$(forward 2) || exit 1
if awk -v a="$p1" -v b="$p2" -v r="$min_p2_ratio" 'BEGIN { exit !(b >= r * a) }'; then
  echo "ok: forward mean displacement P2-P0 $p2 mm, P1 mixed $p1 mm (ratio at least $min_p2_ratio)"
else
  echo "FAIL: forward mean displacement P2-P0 $p2 mm, P1 mixed $p1 mm: ratio under $min_p2_ratio"
  fail=1
fi
# 2 MPI ranks: the rest shape and Table 1's scenario (skull contact on
# the averaged nodal pressure, whose vertex patches reach into the ghost
# cells) give the tumour shift of 1 rank, to 1e-3 (before the contact
# constraints were made consistent across ranks, Table 1 diverged there).
if command -v mpirun >/dev/null; then
  mpirun --allow-run-as-root --oversubscribe -np 2 "$exe" --set "Output/Directory=$out/ranks_2" \
    --set "Output/Write VTU=false" --set "Solver/Check stability=false" \
    --set "Scenario prone/Enabled=false" --set "Scenario drained/Enabled=false" \
    --set "Scenario craniotomy/Enabled=false" prm/brain_in_vivo.prm >"$out/ranks_2.log" 2>&1 ||
    { echo "FAIL: 2 MPI ranks: exit $?"; tail -n 3 "$out/ranks_2.log"; exit 1; }
  tumour_shift() { awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    $1 == "tumour" { print $c["prestressed_centroid_mm"] }' "$1"; }
  one=$(tumour_shift "$out/run/scenario.csv") two=$(tumour_shift "$out/ranks_2/scenario.csv")
  if awk -v a="$one" -v b="$two" 'BEGIN { d = a - b; exit !((d < 0 ? -d : d) <= 1e-3 * a) }'; then
    echo "ok: 2 MPI ranks: Table 1 tumour shift $two mm (1 rank: $one mm)"
  else
    echo "FAIL: 2 MPI ranks: Table 1 tumour shift $two mm, 1 rank $one mm"
    fail=1
  fi
fi
exit $fail
