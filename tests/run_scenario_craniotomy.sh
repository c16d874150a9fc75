#!/bin/bash
# Scenario/Craniotomy against its meaning, nothing else changed:
# 1. the block of block_drained.prm (immersed, resting on a floor) with a
#    ball of 6 mm radius around the middle of its base taken out of the
#    floor: the 5 nodes in it lose their contact and the block sags into
#    the hole (the pre-stressed model; the stress-free one carries no force
#    there and does not move);
# 2. prm/brain.prm (supine, 100 Pa of CSF pressure) with an opening of 30
#    mm radius at the occiput: the pressure faces in it are at 0 Pa, and
#    the pressure on the rest of the surface pushes the brain out through
#    the opening.
# In both, tests/check_craniotomy.py reads scenario.vtu with VTK: no node in
# the opening in contact, its nodes moving out through it.
#
# usage: run_scenario_craniotomy.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
out=$2
here=$(dirname "$0")
rm -rf "$out"
mkdir -p "$out"
# run NAME SCENE REGEX BALL(4) LEAST_OUTWARD_MM [--set ...]
run() {
  local name=$1 scene=$2 regex=$3 ball=("$4" "$5" "$6" "$7") least=$8
  shift 8
  "$exe" --set "Output/Directory=$out/$name" --set "Scenario/Tissue body force=0, 0, 0" \
    --set "Scenario/Craniotomy=sphere: ${ball[0]}, ${ball[1]}, ${ball[2]}, ${ball[3]}" \
    "$@" "$scene" >"$out/$name.log" 2>&1 ||
    { echo "FAIL: $name: the run failed"; tail -n 20 "$out/$name.log"; exit 1; }
  grep -E "$regex" "$out/$name.log" ||
    { echo "FAIL: $name: not /$regex/"; grep Scenario "$out/$name.log"; exit 1; }
  /usr/bin/python3 "$here/check_craniotomy.py" "$out/$name/scenario.vtu" "${ball[@]}" "$least" ||
    { echo "FAIL: $name"; exit 1; }
}
run block tests/scenes/block_drained.prm \
  "radius 6 mm \(5 surface nodes freed from the skull" 10 10 0 6 0.03 \
  --set "Scenario/Fluid level="
run brain prm/brain.prm \
  "radius 30 mm \([1-9][0-9]* surface nodes freed from the skull, [1-9][0-9]* pressure faces at 0 Pa\)" \
  0 -100 0 30 0.2
