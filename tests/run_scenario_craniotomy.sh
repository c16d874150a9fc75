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
# 3. a ball in a spherical cavity (tests/scenes/dome_in_cavity.prm: a dome
#    hanging 0.5 mm above a spherical skull, pressed onto it by 3 g) with a
#    cap of 15 mm radius around the pole removed, given as a surface file
#    (meshes/opening_pole.off): the dome moves into the opening, by more
#    than the 0.5 mm that separate it from where the skull was (the check
#    takes the nodes within 13.5 mm of the pole: inside the faceted
#    sphere).
# In all, tests/check_craniotomy.py reads scenario.vtu with VTK: no node in
# the opening in contact, its nodes moving out through it.
#
# usage: run_scenario_craniotomy.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
out=$2
here=$(dirname "$0")
rm -rf "$out"
mkdir -p "$out"
# run NAME SCENE REGEX BALL(4) LEAST_OUTWARD_MM CRANIOTOMY [--set ...]
# (CRANIOTOMY empty: the ball itself, and no tissue body force)
run() {
  local name=$1 scene=$2 regex=$3 ball=("$4" "$5" "$6" "$7") least=$8
  local opening=$9 field=()
  shift 9
  if [ -z "$opening" ]; then
    opening="sphere: ${ball[0]}, ${ball[1]}, ${ball[2]}, ${ball[3]}"
    field=(--set "Scenario/Tissue body force=0, 0, 0")
  fi
  "$exe" --set "Output/Directory=$out/$name" "${field[@]}" \
    --set "Scenario/Craniotomy=$opening" \
    "$@" "$scene" >"$out/$name.log" 2>&1 ||
    { echo "FAIL: $name: the run failed"; tail -n 20 "$out/$name.log"; exit 1; }
  grep -E "$regex" "$out/$name.log" ||
    { echo "FAIL: $name: not /$regex/"; grep Scenario "$out/$name.log"; exit 1; }
  /usr/bin/python3 "$here/check_craniotomy.py" "$out/$name/scenario.vtu" "${ball[@]}" "$least" ||
    { echo "FAIL: $name"; exit 1; }
}
run block tests/scenes/block_drained.prm \
  "radius 6 mm \(5 surface nodes freed from the skull" 10 10 0 6 0.03 "" \
  --set "Scenario/Fluid level="
run brain prm/brain.prm \
  "radius 30 mm \([1-9][0-9]* surface nodes freed from the skull, [1-9][0-9]* pressure faces at 0 Pa\)" \
  0 -100 0 30 0.2 ""
run dome tests/scenes/dome_in_cavity.prm \
  "inside of the surface meshes/opening_pole.off \([1-9][0-9]* surface nodes freed from the skull" \
  0 0 0 13.5 0.6 "surface: meshes/opening_pole.off"
