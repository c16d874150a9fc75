#!/bin/bash
# Error test of a companion tool (restshape-mesh, restshape-brain-labels):
# bad input gives exactly one line on stderr matching REGEX, exit code 1 (no
# crash), and existing output files (the mesh and the skull) are left
# untouched.
#
# usage: run_mesher_error.sh TOOL OUTPUT_DIRECTORY REGEX ARGS...
# (ARGS may use @OUT@ for the output directory)
set -u
exe=$1
out=$2
regex=$3
shift 3
rm -rf "$out"
mkdir -p "$out"
echo "earlier result" >"$out/mesh.msh"
echo "earlier skull" >"$out/skull.off"
cp "$out/mesh.msh" "$out/sentinel"
cp "$out/skull.off" "$out/skull_sentinel"
args=()
for a in "$@"; do args+=("${a//@OUT@/$out}"); done
"$exe" "${args[@]}" >"$out/stdout" 2>"$out/stderr"
code=$?
fail() {
  echo "FAIL: $1"
  echo "--- exit code $code; stderr:"
  cat "$out/stderr"
  exit 1
}
[ "$code" -eq 1 ] || fail "exit code $code, expected 1"
[ "$(wc -l <"$out/stderr")" -eq 1 ] || fail "expected exactly one line on stderr"
grep -qE -- "$regex" "$out/stderr" || fail "stderr does not match /$regex/"
cmp -s "$out/mesh.msh" "$out/sentinel" || fail "an earlier mesh was overwritten"
cmp -s "$out/skull.off" "$out/skull_sentinel" || fail "an earlier skull was overwritten"
[ -z "$(ls -A "$out" | grep -v -E '^(mesh.msh|skull.off|sentinel|skull_sentinel|stdout|stderr)$')" ] ||
  fail "files were left: $(ls -A "$out")"
echo "ok: $(cat "$out/stderr")"
