#!/bin/bash
# Orientation: the scene of tests/scenes/block_drained.prm (a block on a
# floor, immersed, drained to half its height) with its gravity turned by
# 20 degrees about y, against the same scene turned as a whole by 90
# degrees about x, (x, y, z) -> (x, -z, y): the mesh (as VTU) and the floor
# (tests/rotate_scene.py), gravity (0, 9.81, 0), the fixed components
# (xy -> xz), the fluid level (0, -10, 0) and the scenario's rotation (20
# degrees about the turned y axis, which is z). The turned run must give
# the turned shifts of every tissue for both models and the turned floor
# force; an axis mixed up anywhere (a rotation applied in the wrong frame
# or order, a level or fixed component left behind) would not.
#
# usage: run_scenario_orientation.sh RESTSHAPE OUTPUT_DIRECTORY [--set ...]
# (further arguments go to both runs: e.g. the fluid as a hydrostatic
# pressure, whose free surface must turn with the scene as well)
set -u
exe=$1
out=$2
shift 2
here=$(dirname "$0")
rm -rf "$out"
mkdir -p "$out"
/usr/bin/python3 "$here/rotate_scene.py" meshes/block_tet.msh meshes/floor.off "$out" ||
  { echo "FAIL: cannot turn the scene"; exit 1; }
common=(--set "Output/Write VTU=false" "$@")
"$exe" "${common[@]}" --set "Output/Directory=$out/upright" \
  --set "Scenario/Gravity rotation=0, 20, 0" tests/scenes/block_drained.prm >"$out/upright.log" 2>&1 ||
  { echo "FAIL: the upright run failed"; tail -n 20 "$out/upright.log"; exit 1; }
"$exe" "${common[@]}" --set "Output/Directory=$out/turned" \
  --set "Mesh/File=$out/block_turned.vtu" --set "Contact/Obstacle file=$out/floor_turned.off" \
  --set "Loads/Gravity=0, 9.81, 0" --set "Boundary conditions/Fixed labels=1:xz" \
  --set "Scenario/Fluid level=0, -10, 0" --set "Scenario/Gravity rotation=0, 0, 20" \
  tests/scenes/block_drained.prm >"$out/turned.log" 2>&1 ||
  { echo "FAIL: the turned run failed"; tail -n 20 "$out/turned.log"; exit 1; }
/usr/bin/python3 - "$out/upright" "$out/turned" <<'PY'
import csv, json, sys

import numpy as np

upright, turned = sys.argv[1:3]
turn = lambda v: np.array([v[0], -v[2], v[1]])
failures = []
rows = [list(csv.DictReader(open(d + "/scenario.csv"))) for d in (upright, turned)]
for a, b in zip(*rows):
    for model in ("prestressed", "stress_free"):
        u = [float(a["%s_centroid_%s_mm" % (model, c)]) for c in "xyz"]
        t = [float(b["%s_centroid_%s_mm" % (model, c)]) for c in "xyz"]
        if np.linalg.norm(turn(u) - t) > 1e-6 * (1 + np.linalg.norm(u)):
            failures.append("%s centroid shift %s, turned %s" % (model, u, t))
        m = "%s_max_mm" % model
        if abs(float(a[m]) - float(b[m])) > 1e-6 * (1 + float(a[m])):
            failures.append("%s largest shift %s, turned %s" % (model, a[m], b[m]))
forces = [np.array(json.load(open(d + "/summary.json"))["scenario_contact_force_N"])
          for d in (upright, turned)]
if np.linalg.norm(turn(forces[0]) - forces[1]) > 1e-9 * (1 + np.linalg.norm(forces[0])):
    failures.append("floor force %s, turned %s" % (forces[0], forces[1]))
shift = float(rows[0][0]["prestressed_centroid_mm"])
if not shift > 1e-3:
    failures.append("the block does not move (%g mm)" % shift)
if failures:
    print("FAIL: " + "; ".join(failures))
    sys.exit(1)
print("ok: the turned scene gives the turned shifts (centroid %.6f mm) "
      "and floor force %s N" % (shift, forces[1]))
PY
