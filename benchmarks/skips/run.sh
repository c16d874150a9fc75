#!/bin/bash
# What skipping unneeded work saves, in one run: prm/brain.prm (whole inverse
# iteration, no prestress comparison) as it is, then without VTU output,
# without the skull (no obstacle: no AABB tree, no contact search, no active
# set), and without the CSF pressure (no pressure face loop). The last two
# change the physics (the brain does not touch the skull at the converged
# rest shape, so the rest shape changes little); they show the cost of the
# feature, which the program only pays when a scene asks for it. Prints wall
# times, the TimerOutput seconds of output and contact search, and the ratio
# to the full scene.
#
# usage: benchmarks/skips/run.sh [--coarse]
#   --coarse: forward solve only (the version run in the tests)
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/skips).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/skips}
inverse=true
[ "${1:-}" = --coarse ] && inverse=false
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

echo "machine: $(machine); inverse: $inverse"
echo
echo "| variant | seconds | ratio to full | output (s) | contact search (s) |"
echo "| --- | --- | --- | --- | --- |"
status=0
full=""
for variant in full no_vtu no_skull no_pressure; do
  case $variant in
  full) set=() ;;
  no_vtu) set=(--set "Output/Write VTU=false") ;;
  no_skull) set=(--set "Contact/Obstacle file=") ;;
  no_pressure) set=(--set "Loads/Surface pressure=0") ;;
  esac
  dir=$out/$variant
  rm -rf "$dir"
  if ! "$exe" --set "Output/Directory=$dir" --set "Inverse problem/Enabled=$inverse" \
    --set "Scenario/Enabled=false" "${set[@]}" prm/brain.prm >"$dir.log" 2>&1; then
    echo "| $variant | failed: $(tail -n 1 "$dir.log") |"
    status=1
    continue
  fi
  seconds=$(value wall_seconds "$dir/summary.json")
  [ -z "$full" ] && full=$seconds
  printf '| %s | %.2f | %.2f | %s | %s |\n' "$variant" "$seconds" \
    "$(awk -v a="$seconds" -v b="$full" 'BEGIN { print a / b }')" \
    "$(timer_seconds Output "$dir.log")" "$(timer_seconds 'Contact search' "$dir.log")"
done
# Skipping the VTU output must not change the result.
max_u() { grep -o '"max_displacement_mm": [-0-9.e+]*' "$out/$1/summary.json" | awk '{ print $2 }'; }
echo "largest displacement (mm): full $(max_u full), no_vtu $(max_u no_vtu)"
[ "$(max_u full)" = "$(max_u no_vtu)" ] ||
  { echo "FAILED: without VTU output the result changed"; status=1; }
exit $status
