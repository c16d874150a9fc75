#!/bin/bash
# Interrupted runs: a run killed (SIGTERM, SIGINT, SIGHUP) at moments spread
# over a whole run leaves a directory that holds either the previous result
# untouched or the new run's files only, with a summary.json that says it was
# interrupted (or converged, if the run finished first); never a mix, never
# a temporary file.
#
# usage: run_interrupts.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
# Job control: background runs get SIGINT as from a terminal (a shell
# without it starts them with SIGINT ignored).
set -m
exe=$1
work=$2
scene=prm/column_inverse.prm
rounds=9
rm -rf "$work"
mkdir -p "$work"
out=$work/result
fail() {
  echo "FAIL (round $round, signal $signal after $delay s): $1"
  ls -la --time-style=full-iso "$out"
  cat "$out/summary.json" 2>/dev/null
  echo "== the run's screen output:"
  tail -n 20 "$work/round_$round.log" 2>/dev/null
  exit 1
}

# The previous result, and how long a run takes.
round=0 signal=none delay=0
start=$(date +%s%N)
"$exe" "$scene" --set "Output/Directory=$out" >"$work/first.log" 2>&1 || fail "the first run failed"
duration_ms=$((($(date +%s%N) - start) / 1000000))
echo "a whole run: $duration_ms ms"

RANDOM=20261127
signals=(TERM INT HUP)
for round in $(seq 1 $rounds); do
  signal=${signals[$((round % 3))]}
  # Moments spread over the run: the k-th round within the k-th ninth.
  delay_ms=$((duration_ms * (round - 1) / rounds + RANDOM % (duration_ms / rounds + 1)))
  delay=$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))
  cp "$out/summary.json" "$work/previous_summary.json"
  sleep 1.1 # mtimes before the marker are older than it
  touch "$work/marker"
  sleep 0.1
  gravity=$(printf '0, 0, -%d.%d' $((8 + round % 3)) "$round")
  "$exe" "$scene" --set "Output/Directory=$out" --set "Loads/Gravity=$gravity" \
    >"$work/round_$round.log" 2>&1 &
  pid=$!
  sleep "$delay"
  kill -s "$signal" "$pid" 2>/dev/null
  wait "$pid"
  code=$?
  leftovers=$(ls -A "$out" | grep -E '\.tmp-|^\.staged-|^\.tmp-')
  [ -z "$leftovers" ] || fail "temporary files left: $leftovers"
  newer=$(find "$out" -type f -newer "$work/marker" | wc -l)
  older=$(find "$out" -type f ! -newer "$work/marker" | wc -l)
  if cmp -s "$out/summary.json" "$work/previous_summary.json" && [ "$newer" -eq 0 ]; then
    state="the previous result, untouched"
  elif [ "$older" -eq 0 ]; then
    if grep -q '"converged": true' "$out/summary.json"; then
      [ "$code" -eq 0 ] || fail "exit code $code for a finished run"
      state="the new result (the run finished)"
    else
      grep -q "\"failure\": \"interrupted by SIG$signal" "$out/summary.json" ||
        fail "summary.json does not say the run was interrupted by SIG$signal"
      [ "$code" -ge 128 ] || fail "exit code $code for an interrupted run"
      state="the new run's files, summary: interrupted (exit $code)"
    fi
  else
    fail "a mix: $newer files of the new run beside $older of the previous one"
  fi
  echo "round $round: SIG$signal after $delay s: $state"
  # The next round starts from a finished result.
  if ! grep -q '"converged": true' "$out/summary.json"; then
    "$exe" "$scene" --set "Output/Directory=$out" >"$work/restore.log" 2>&1 ||
      fail "the run that restores a result failed"
  fi
done
echo "ok: $rounds interrupted runs left the previous result or the new one"
