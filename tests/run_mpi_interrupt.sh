#!/bin/bash
# An MPI run interrupted: SIGTERM to mpirun (what a user's kill does) and
# SIGTERM to the ranks themselves (what a batch system's cancel does), once
# the direct inverse has begun. Every rank ends within a few seconds, no
# temporary file is left, summary.json says "interrupted by SIGTERM", rank 0
# prints one line saying so, and the exit code is not 0 (the ranks exit 143;
# mpirun's own code is Open MPI's: 1 when mpirun itself got the signal).
#
# usage: run_mpi_interrupt.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
fail() {
  echo "FAIL ($target): $1"
  tail -n 20 "$work/$target.log"
  pkill -KILL -f "Output/Directory=$work/" 2>/dev/null
  exit 1
}
for target in mpirun ranks; do
  out=$work/$target
  mpirun --allow-run-as-root --oversubscribe -np 2 "$exe" \
    --set "Output/Directory=$out" --set "Discretization/Polynomial degree=2" \
    --set "Output/Write VTU=false" prm/brain.prm >"$work/$target.log" 2>&1 &
  pid=$!
  # Wait for the direct inverse's first Newton step (at most 120 s).
  for _ in $(seq 1 1200); do
    grep -q "Newton  1" "$work/$target.log" && break
    kill -0 $pid 2>/dev/null || fail "the run ended before it could be interrupted"
    sleep 0.1
  done
  if [ $target = mpirun ]; then
    kill -TERM $pid
  else
    pkill -TERM -f "^$exe --set Output/Directory=$out"
  fi
  wait $pid
  code=$?
  sleep 2
  pgrep -f "Output/Directory=$out" >/dev/null && fail "a rank is still running"
  [ $code -ne 0 ] || fail "exit code 0"
  grep -q '"failure": "interrupted by SIGTERM' "$out/summary.json" ||
    fail "summary.json does not say the run was interrupted: $(cat "$out/summary.json")"
  grep -q "^Interrupted by SIGTERM" "$work/$target.log" || fail "no line says the run was interrupted"
  ls -a "$out" | grep -q "tmp" && fail "temporary files left: $(ls -a "$out" | grep tmp)"
  echo "SIGTERM to $target: mpirun exit code $code, every rank ended, summary.json says interrupted"
done
echo PASSED
