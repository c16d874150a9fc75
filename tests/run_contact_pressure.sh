#!/bin/bash
# The contact pressure as a field users read (tests/check_contact_pressure.py,
# VTK's reader): Hertz's hemisphere (prm/hertz.prm, Q2) with the field's
# peak within 10 % of Hertz's p0 and no node above NEIGHBOUR_HERTZ (3) times
# its active neighbours' mean; the brain's Table 1 scenario (prm/brain.prm,
# P1 in the skull) with no node above NEIGHBOUR_BRAIN (5) times its
# neighbours' mean and the peak at most PEAK_BRAIN (5) times the mean (the
# nodal force over its area had a node 341 times its neighbours' mean).
# usage: run_contact_pressure.sh RESTSHAPE OUTPUT_DIRECTORY
set -eu -o pipefail
exe=$1
out=$2
here=$(dirname "$0")
rm -rf "$out"
mkdir -p "$out"
"$exe" --set "Output/Directory=$out/hertz" prm/hertz.prm >"$out/hertz.log" 2>&1 ||
  { echo "FAIL: hertz"; tail -n 3 "$out/hertz.log"; exit 1; }
force=$(grep '"contact_force_N"' "$out/hertz/summary.json" | sed 's/.*, *\([^]]*\)\].*/\1/')
/usr/bin/python3 "$here/check_contact_pressure.py" "$out/hertz/solution-0000.vtu" \
  --hertz "$force" 10000 0.3 0.05 --peak-tolerance 0.1 \
  --max-neighbour-ratio "${NEIGHBOUR_HERTZ:-3}"
"$exe" --set "Output/Directory=$out/brain" prm/brain.prm >"$out/brain.log" 2>&1 ||
  { echo "FAIL: brain"; tail -n 3 "$out/brain.log"; exit 1; }
/usr/bin/python3 "$here/check_contact_pressure.py" "$out/brain/scenario.vtu" \
  --max-neighbour-ratio "${NEIGHBOUR_BRAIN:-5}" --max-peak-over-mean "${PEAK_BRAIN:-5}"
