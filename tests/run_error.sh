#!/bin/bash
# Error test: restshape must reject bad input with exactly one line on stderr
# that matches REGEX, a non-zero exit code below 128 (no crash), no stack
# trace, and leave an earlier result in the output directory untouched.
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

"$exe" --set "Output/Directory=$out" "$@" >"$out/stdout" 2>"$out/stderr"
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
cmp -s "$out/summary.json" "$out/sentinel" || fail "an earlier result was overwritten"
[ -z "$(ls "$out" | grep -v -E '^(summary.json|sentinel|stdout|stderr)$')" ] || fail "files were written: $(ls "$out")"
echo "ok: $(cat "$out/stderr")"
