#!/bin/bash
# The brain's skull moved by DX mm along x (written to the output directory)
# must be refused before solving, with the counts and both boxes.
#
# usage: run_moved_obstacle.sh RUN_ERROR RESTSHAPE OUTPUT_DIRECTORY DX REGEX ARGS...
set -u
run_error=$1
exe=$2
out=$3
dx=$4
regex=$5
shift 5
mkdir -p "$out.data"
awk -v dx="$dx" 'BEGIN { OFMT = CONVFMT = "%.12g" }
  NF == 0 { print; next }
  { line++ }
  line == 2 { nv = $1 }
  line > 2 && line <= 2 + nv { $1 = $1 + dx }
  { print }' \
  meshes/brain_skull.off >"$out.data/skull.off"
exec "$run_error" "$exe" "$out" 1 "$regex" \
  --set "Contact/Obstacle file=$out.data/skull.off" "$@"
