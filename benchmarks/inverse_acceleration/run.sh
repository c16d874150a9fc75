#!/bin/bash
# Benchmark: the inverse iteration with the paper's update ("none") and with
# Anderson acceleration, each with the consistent and the SOFA-style
# ("warped") tangent, on the same scene and tolerance, in one run. Prints a
# markdown table: forward solves, Newton iterations, wall time, and ratios
# to the paper's method (none + warped). Fails unless every variant
# converges and Anderson + consistent takes at most half the paper's Newton
# iterations.
#
# usage: benchmarks/inverse_acceleration/run.sh [--coarse] [SCENE.prm] [--set ...]
#   --coarse: P1 elements and a looser tolerance (the version run in the tests)
# Run from the repository root after building (build/restshape).
set -u
exe=${RESTSHAPE:-build/restshape}
here=$(cd "$(dirname "$0")" && pwd)
out=${OUT:-output/benchmarks/inverse_acceleration}
scene=$here/scene.prm
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
  --coarse) extra+=(--set "Discretization/Polynomial degree=1" --set "Inverse problem/Tolerance=1e-3") ;;
  --set) extra+=(--set "$2"); shift ;;
  *) scene=$1 ;;
  esac
  shift
done
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

echo "scene: $scene ${extra[*]:-}"
echo "machine: $(machine)"
echo
echo "| update | tangent | converged | iterations | forward solves | Newton iterations | wall s | forward solves / paper | Newton / paper | time / paper |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for acceleration in none anderson; do
  for tangent in warped consistent; do
    dir=$out/${acceleration}_$tangent
    "$exe" "${extra[@]}" --set "Inverse problem/Acceleration=$acceleration" \
      --set "Discretization/Tangent=$tangent" --set "Output/Directory=$dir" "$scene" >"$dir.log" 2>&1
    s=$dir/summary.json
    converged=$(value converged "$s")
    [ "$converged" = "true" ] || status=1
    its=$(value inverse_iterations "$s")
    fs=$(value forward_solves "$s")
    newton=$(value newton_iterations "$s")
    wall=$(value wall_seconds "$s")
    if [ "$acceleration$tangent" = "nonewarped" ]; then
      fs0=$fs newton0=$newton wall0=$wall
    fi
    awk -v a="$acceleration" -v t="$tangent" -v c="$converged" -v i="$its" -v f="$fs" -v n="$newton" \
      -v w="$wall" -v f0="$fs0" -v n0="$newton0" -v w0="$wall0" \
      'BEGIN { printf "| %s | %s | %s | %s | %s | %s | %.2f | %.2f | %.2f | %.2f |\n", a, t, c, i, f, n, w, f/f0, n/n0, w/w0 }'
  done
done
# The figure this benchmark stands for (not a time): Anderson with the
# consistent tangent needs at most half the paper's Newton iterations
# (measured 0.40 coarse).
awk -v n="$newton" -v n0="$newton0" 'BEGIN { exit !(n <= 0.5 * n0) }' || {
  echo "FAIL: anderson + consistent took $newton Newton iterations, the paper's method $newton0 (expected at most half)"
  status=1
}
exit $status
