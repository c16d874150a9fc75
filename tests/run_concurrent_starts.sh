#!/bin/bash
# Runs started side by side, as ctest -j, a study or a user's script start
# them: every one of 150 starts (6 at a time) initialises MPI. Open MPI 4's
# isolated singletons share one session directory, which a run that ends
# removes while another starts; about 1 % of such starts failed in MPI_Init
# with exit 1 before RestShape made singletons go without it.
#
# usage: run_concurrent_starts.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
work=$2
workers=6
starts=25
rm -rf "$work"
mkdir -p "$work"
worker() {
  for i in $(seq 1 $starts); do
    "$exe" --version >"$work/start_$1.log" 2>&1 ||
      cp "$work/start_$1.log" "$work/failed_$1_$i.log"
  done
}
for w in $(seq 1 $workers); do worker "$w" & done
wait
failed=$(ls "$work" | grep -c '^failed_')
echo "$((workers * starts)) starts, $failed failed"
if [ "$failed" -ne 0 ]; then
  head -5 "$work"/failed_*.log | head -20
  exit 1
fi
echo ok
