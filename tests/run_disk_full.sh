#!/bin/bash
# A disk that fills during the run: the output directory on a 200 kB tmpfs.
# The run exits 5 with one line on stderr that says the results could not
# be written, removes its partial files and leaves a summary.json that
# says so (README, "Exit codes"). Skipped (77) where tmpfs cannot be
# mounted (not root, or a container without the capability).
# usage: run_disk_full.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
work=$2
mkdir -p "$work"
disk=$(mktemp -d "$work/disk.XXXXXX")
mount -t tmpfs -o size=200k tmpfs "$disk" 2>/dev/null || { echo "SKIPPED: cannot mount a tmpfs"; rmdir "$disk"; exit 77; }
trap 'umount "$disk"; rmdir "$disk"' EXIT
"$exe" --set "Output/Directory=$disk/out" prm/brain.prm >"$work/run.log" 2>"$work/stderr.txt"
code=$?
fail() { echo "FAIL: $1"; cat "$work/stderr.txt"; ls -la "$disk/out"; exit 1; }
[ $code -eq 5 ] || fail "exit $code, expected 5"
[ "$(wc -l <"$work/stderr.txt")" -eq 1 ] || fail "not one line on stderr"
grep -q "cannot write the results.*disk full" "$work/stderr.txt" || fail "the line does not say the disk is full"
left=$(ls "$disk/out" | grep -v '^summary.json$')
[ -z "$left" ] || fail "partial results left: $left"
python3 -c "
import json, sys
s = json.load(open('$disk/out/summary.json'))
sys.exit(0 if s['converged'] is False and 'cannot write' in s['failure'] else 1)" ||
  fail "summary.json does not record the failure"
echo "ok: exit 5, $(cat "$work/stderr.txt")"
