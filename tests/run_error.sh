#!/bin/bash
# Error test: restshape must reject bad input with exactly one line on stderr
# that matches REGEX, a non-zero exit code below 128 (no crash), no stack
# trace, and leave an earlier result in the output directory untouched.
# EXIT_CODE 2 (a solver that failed): the one line, and a summary.json that
# says "converged": false with the failure (its figures), instead.
# EXIT_CODE 4 (a scenario failed): the one line, and a summary.json that
# says "converged": true and "scenarios_converged": false.
# Environment: STDOUT_REGEX, if set, must match the screen output (stdout);
# MPI_RANKS, if set, runs restshape on that many ranks under mpirun.
#
# usage: run_error.sh RESTSHAPE OUTPUT_DIRECTORY EXIT_CODE REGEX ARGS...
set -u
exe=$1
out=$2
expected_code=$3
regex=$4
shift 4

rm -rf "$out"
mkdir -p "$out"
echo '{"earlier": "result"}' >"$out/summary.json"
cp "$out/summary.json" "$out/sentinel"

launcher=()
if [ -n "${MPI_RANKS:-}" ]; then
  launcher=(mpirun --allow-run-as-root --oversubscribe --quiet -np "$MPI_RANKS")
fi
"${launcher[@]}" "$exe" --set "Output/Directory=$out" "$@" >"$out/stdout" 2>"$out/stderr"
code=$?
fail() {
  echo "FAIL: $1"
  echo "--- exit code $code; stderr:"
  cat "$out/stderr"
  exit 1
}
[ "$code" -ne 0 ] || fail "exit code 0 for bad input"
[ "$code" -lt 128 ] || fail "crashed (signal)"
[ "$code" -eq "$expected_code" ] || fail "exit code $code, expected $expected_code"
[ "$(wc -l <"$out/stderr")" -eq 1 ] || fail "expected exactly one line on stderr"
grep -qiE 'stacktrace|stack trace|--------' "$out/stderr" && fail "stack trace or deal.II banner on stderr"
grep -qE -- "$regex" "$out/stderr" || fail "stderr does not match /$regex/"
if [ -n "${STDOUT_REGEX:-}" ]; then
  grep -qE -- "$STDOUT_REGEX" "$out/stdout" || fail "stdout does not match /$STDOUT_REGEX/"
fi
if [ "$expected_code" -eq 2 ]; then
  grep -q '"converged": false' "$out/summary.json" || fail "summary.json does not say converged: false"
  grep -q '"failure"' "$out/summary.json" || fail "summary.json does not give the failure"
  grep -qiE 'nan|inf' "$out/summary.json" && fail "NaN or Inf in summary.json"
elif [ "$expected_code" -eq 4 ]; then
  grep -q '"converged": true' "$out/summary.json" || fail "summary.json does not say converged: true"
  grep -q '"scenarios_converged": false' "$out/summary.json" || fail "summary.json does not say scenarios_converged: false"
  grep -qiE 'nan|inf' "$out/summary.json" && fail "NaN or Inf in summary.json"
else
  cmp -s "$out/summary.json" "$out/sentinel" || fail "an earlier result was overwritten"
  [ -z "$(ls "$out" | grep -v -E '^(summary.json|sentinel|stdout|stderr)$')" ] || fail "files were written: $(ls "$out")"
fi
echo "ok: $(cat "$out/stderr")"
