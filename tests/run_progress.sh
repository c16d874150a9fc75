#!/bin/bash
# A line at least every few seconds: a run whose phases stay silent for
# seconds (a P2 inverse's factorisations and Krylov solves) with the
# heartbeat at 1 s (RESTSHAPE_PROGRESS_SECONDS=1). Each line of its screen
# output is timed as it arrives: no gap may exceed 1 s by more than the
# longest line-free stretch a heartbeat cannot cut (4 s allowed), and the
# heartbeat must have spoken ("  ... PHASE (N s into the run)").
#
# usage: run_progress.sh RESTSHAPE OUTPUT_DIRECTORY ARGS...
set -u
exe=$1
out=$2
shift 2
rm -rf "$out"
mkdir -p "$out"
RESTSHAPE_PROGRESS_SECONDS=1 python3 - "$out" "$exe" --set "Output/Directory=$out/run" "$@" <<'PY'
import subprocess, sys, time
out, cmd = sys.argv[1], sys.argv[2:]
start = time.monotonic()
last, gaps, beats = start, [], 0
p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
with open(out + "/stdout", "w") as log:
    for line in p.stdout:
        now = time.monotonic()
        gaps.append((now - last, line.strip()))
        last = now
        beats += line.startswith("  ... ")
        log.write(f"{now - start:8.2f} {line}")
code = p.wait()
if code != 0:
    sys.exit(f"FAIL: exit code {code}; {out}/stdout")
gap, after = max(gaps)
if gap > 4:
    sys.exit(f"FAIL: {gap:.1f} s without a line before '{after}'")
if beats == 0:
    sys.exit(f"FAIL: no heartbeat line in {time.monotonic() - start:.0f} s (a scene too fast to test?)")
print(f"ok: {len(gaps)} lines, {beats} of the heartbeat, longest gap {gap:.1f} s")
PY
