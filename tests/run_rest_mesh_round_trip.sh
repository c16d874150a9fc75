#!/bin/bash
# The round trip of a rest shape: an inverse run writes rest_shape.msh; a
# forward run that takes it as Mesh/File (stress-free, the same loads, no
# inverse) must land on the equilibrium the inverse found, which the file
# carries, to the inverse's largest error (plus SLACK mm, default 1e-6);
# from a file without it (MPI), reach the target the file carries to the
# error the inverse run reported.
#
# usage: run_rest_mesh_round_trip.sh RESTSHAPE OUT SCENE.prm [--set ...]
# Environment: SLACK (mm); INVERSE: the output directory of an inverse run
# of the same SCENE.prm and settings (a scene test's) to take instead of
# running it again.
set -u
exe=$1
out=$2
scene=$3
shift 3
slack=${SLACK:-1e-6}
rm -rf "$out"
mkdir -p "$out"
if [ -n "${INVERSE:-}" ]; then
  [ -f "$INVERSE/rest_shape.msh" ] || { echo "no rest_shape.msh in $INVERSE"; exit 1; }
  ln -s "$(realpath "$INVERSE")" "$out/inverse"
else
  "$exe" "$@" --set "Output/Directory=$out/inverse" "$scene" >"$out/inverse.log" 2>&1 ||
    { echo "inverse run failed"; tail "$out/inverse.log"; exit 1; }
fi
"$exe" "$@" --set "Inverse problem/Enabled=false" \
  --set "Scenario/Enabled=false" \
  --set "Mesh/File=$out/inverse/rest_shape.msh" \
  --set "Output/Directory=$out/forward" "$scene" >"$out/forward.log" 2>&1 ||
  { echo "forward run from rest_shape.msh failed"; tail "$out/forward.log"; exit 1; }
value() { grep "\"$1\"" "$2" | sed 's/.*: \([^,]*\),*/\1/'; }
# A rest_shape.msh that carries the inverse run's equilibrium: the forward
# run must land on it to the inverse's own accuracy (its largest error:
# where the target crosses the obstacle, the error against the target
# includes what no equilibrium reaches).
if grep -q '"equilibrium_distance_max_mm"' "$out/forward/summary.json"; then
  bound=$(value max_error_mm "$out/inverse/summary.json")
  for key in equilibrium_distance_mean_mm equilibrium_distance_max_mm; do
    reached=$(value $key "$out/forward/summary.json")
    echo "$key: $reached (the inverse's largest error $bound)"
    awk -v b="$reached" -v a="$bound" -v s="$slack" 'BEGIN { exit !(b != "" && b <= a + s) }' ||
      { echo "FAIL: the forward run from rest_shape.msh misses the inverse's equilibrium"; exit 1; }
  done
  echo ok
  exit 0
fi
for key in mean_error_mm max_error_mm; do
  reported=$(value $key "$out/inverse/summary.json")
  reached=$(value $key "$out/forward/summary.json")
  echo "$key: inverse reported $reported; forward from rest_shape.msh: $reached"
  awk -v a="$reported" -v b="$reached" -v s="$slack" 'BEGIN { exit !(b != "" && b <= a + s) }' ||
    { echo "FAIL: the rest shape does not reach its target as the inverse reported"; exit 1; }
done
echo ok
