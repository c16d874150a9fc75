#!/bin/bash
# A run that must succeed (exit 0) and say something: its screen output
# (stdout) must match REGEX (grep -E), e.g. a warning or a diagnosis.
#
# usage: run_expect.sh RESTSHAPE OUTPUT_DIRECTORY REGEX ARGS...
set -u
exe=$1
out=$2
regex=$3
shift 3
rm -rf "$out"
mkdir -p "$out"
"$exe" --set "Output/Directory=$out" "$@" >"$out/stdout" 2>"$out/stderr"
code=$?
if [ "$code" -ne 0 ]; then
  echo "FAIL: exit code $code; stderr:"
  cat "$out/stderr"
  exit 1
fi
grep -E -- "$regex" "$out/stdout" || { echo "FAIL: the output does not match /$regex/"; tail -n 20 "$out/stdout"; exit 1; }
echo ok
