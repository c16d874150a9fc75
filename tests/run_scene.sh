#!/bin/bash
# Scene test: run restshape on tests/scenes/NAME.prm and compare every file of
# tests/scenes/NAME.expected/ with the same file of the output, with numdiff.
# Timing fields (JSON keys and CSV columns containing "seconds") and the
# version and git revision of the build are dropped before the comparison. Tolerances: tests/scenes/NAME.numdiff (numdiff
# options), default "-a 1e-8 -r 1e-6" (a field passes if either holds).
#
# usage: run_scene.sh RESTSHAPE NAME OUTPUT_DIRECTORY [--set ...]
set -u
exe=$1
name=$2
out=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
scenes=$here/scenes

rm -rf "$out"
mkdir -p "$out"
# MPI_RANKS=N (environment) runs the scene on N MPI ranks against the same
# expected output: results must agree with the serial run to solver tolerance.
launch=()
if [ -n "${MPI_RANKS:-}" ]; then
  launch=(mpirun --allow-run-as-root --oversubscribe -np "$MPI_RANKS")
fi
if ! "${launch[@]}" "$exe" --set "Output/Directory=$out" "$@" "$scenes/$name.prm" >"$out/screen.log" 2>&1; then
  echo "restshape failed on $name.prm:"
  tail -n 30 "$out/screen.log"
  exit 1
fi

drop_timing() {
  case "$1" in
  *.json) grep -v -E 'seconds|"restshape_version"|"git_revision"' "$1" ;;
  *.csv)
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) keep[i] = ($i !~ /seconds/) }
             { line = ""; for (i = 1; i <= NF; ++i) if (keep[i]) line = line (line == "" ? "" : ",") $i; print line }' "$1"
    ;;
  *) cat "$1" ;;
  esac
}

tolerance="-a 1e-8 -r 1e-6"
[ -f "$scenes/$name.numdiff" ] && tolerance=$(cat "$scenes/$name.numdiff")
status=0
for expected in "$scenes/$name.expected"/*; do
  file=$(basename "$expected")
  if [ ! -f "$out/$file" ]; then
    echo "missing output file: $file"
    status=1
    continue
  fi
  drop_timing "$expected" >"$out/$file.expected"
  drop_timing "$out/$file" >"$out/$file.computed"
  # shellcheck disable=SC2086
  if ! numdiff -q $tolerance -s ' \t\n,:;[]{}"|' "$out/$file.expected" "$out/$file.computed" >/dev/null; then
    echo "== $file differs from the expected output:"
    # shellcheck disable=SC2086
    numdiff $tolerance -s ' \t\n,:;[]{}"|' "$out/$file.expected" "$out/$file.computed" | head -n 40
    status=1
  fi
done
[ $status -eq 0 ] && echo "$name: all files match"
exit $status
