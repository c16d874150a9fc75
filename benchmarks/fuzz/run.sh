#!/bin/bash
# A fuzzing campaign of every reader of user input with libFuzzer.
#
# usage: benchmarks/fuzz/run.sh SECONDS [TARGET...]
#
# Builds the fuzz targets (clang, -fsanitize=fuzzer,address,undefined;
# CMake option RESTSHAPE_FUZZ) in build-fuzz/ unless they are there, runs
# each target for SECONDS from its seeds (tests/fuzz/CMakeLists.txt) and the
# corpus of earlier campaigns (build-fuzz/corpus/TARGET), and prints one
# line per target: executions, coverage (libFuzzer's edges and features),
# corpus size and findings. A finding (a crash, a sanitizer report, an
# exception other than InputError, a hang beyond 30 s, more than 4 GB) is
# saved to build-fuzz/findings/TARGET/; copy it to
# tests/fuzz/regression/TARGET/ once fixed, and the suite replays it.
# Exit code: the number of targets with findings.
set -u
seconds=${1:?usage: run.sh SECONDS [TARGET...]}
shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(gmsh vtk vtu abaqus off stl obj prm nifti)
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
build=${FUZZ_BUILD:-$source_dir/build-fuzz}

if [ ! -x "$build/tests/fuzz/fuzz_${targets[0]}" ] || [ -n "${FUZZ_REBUILD:-}" ]; then
  cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER=clang++ -DRESTSHAPE_FUZZ=ON >/dev/null || exit 100
  cmake --build "$build" -j2 $(printf -- '--target fuzz_%s ' "${targets[@]}") >/dev/null || exit 100
fi

printf '%-8s %12s %10s %9s %8s %8s  %s\n' target executions exec/s coverage features corpus findings
n_failed=0
# The sanitizers' reports of crashing children (".PID" files) stay in
# the build directory.
cd "$build"
for t in "${targets[@]}"; do
  corpus=$build/corpus/$t
  findings=$build/findings/$t
  mkdir -p "$corpus" "$findings"
  # The seeds join the corpus (libFuzzer takes directories).
  while read -r seed; do
    [ -n "$seed" ] && cp -n "$seed" "$corpus/seed-$(basename "$seed")"
  done <"$build/fuzz_seeds_$t.txt"
  log=$build/fuzz_$t.log
  # -fork: a crash or hang is saved and the campaign goes on.
  ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1 \
    "$build/tests/fuzz/fuzz_$t" "$corpus" "$source_dir/tests/fuzz/regression/$t" \
    -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 -malloc_limit_mb=4096 \
    -print_final_stats=1 -artifact_prefix="$findings/" -close_fd_mask=3 \
    -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 -fork=1 >"$log" 2>&1
  executions=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' | awk '{s+=$1} END {print s+0}')
  if [ "$executions" = 0 ]; then
    # -fork prints its own totals: "#N: cov: C ft: F corp: K exec/s: E".
    executions=$(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#')
  fi
  coverage=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+')
  features=$(grep -oE 'ft: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+')
  n_corpus=$(ls "$corpus" | wc -l)
  n_findings=$(ls "$findings" | grep -cE '^(crash|leak|timeout|oom|slow-unit)-')
  rate=$((${executions:-0} / (seconds > 0 ? seconds : 1)))
  printf '%-8s %12s %10s %9s %8s %8s  %s\n' "$t" "${executions:-0}" "$rate" \
    "${coverage:-?}" "${features:-?}" "$n_corpus" "$n_findings"
  [ "$n_findings" -eq 0 ] || n_failed=$((n_failed + 1))
done
exit $n_failed
