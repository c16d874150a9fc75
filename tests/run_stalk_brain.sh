#!/bin/bash
# The default inverse on a brain held only by a small stalk (the synthetic
# segmentation of make_stalk_brain.py, meshed with its segmented skull):
# no tethers, so the buoyed weight must go through the stalk, which it
# would strain by about 2: the run stops at once (exit 2) naming the load
# path and the remedy, with summary.json saying so. With 1 Pa/mm tethers
# (TETHERS=1) the inverse converges instead, within 15 iterations.
#
# usage: run_stalk_brain.sh BUILD_DIRECTORY OUTPUT_DIRECTORY
set -eu
build=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out/mesh"
/usr/bin/python3 "$here/make_stalk_brain.py" "$out/mesh"
"$build/restshape-mesh" --image "$out/mesh/stalk_brain.nii.gz" --out "$out/mesh/stalk.msh" \
  --cell-size "${CELL_SIZE:-8}" --skull-out "$out/mesh/skull.off" \
  --skull-image "$out/mesh/stalk_skull.nii.gz" --skull-facet-size 5 >"$out/mesh.log"
set=(--set "Mesh/File=$out/mesh/stalk.msh" --set "Contact/Obstacle file=$out/mesh/skull.off")
fail() { echo "FAIL: $1"; tail -n 20 "$2"; exit 1; }
if [ -z "${TETHERS:-}" ]; then
  STDOUT_REGEX="Load path at the target: the loads' resultant" \
    "$here/run_error.sh" "$build/restshape" "$out/run" 2 \
    "no rest shape found: the direct inverse failed .*; the load path at the target explains it: .* strains by about [1-9]" \
    "${set[@]}" "$here/data/stalk_brain.prm"
  grep -q "Elastic support stiffness" "$out/run/stderr" || fail "no remedy named" "$out/run/stderr"
else
  "$build/restshape" --set "Output/Directory=$out/run" "${set[@]}" \
    --set "Boundary conditions/Elastic support stiffness=1e3" \
    "$here/data/stalk_brain.prm" >"$out/run.log" 2>&1 || fail "the tethered brain did not converge" "$out/run.log"
  its=$(grep '"inverse_iterations"' "$out/run/summary.json" | tr -dc '0-9')
  echo "inverse iterations: $its"
  [ "$its" -le 15 ] || fail "more than 15 inverse iterations" "$out/run.log"
  grep -q '"contact_conditions_hold": true' "$out/run/summary.json" || fail "contact conditions" "$out/run.log"
fi
echo ok
