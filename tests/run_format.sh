#!/bin/bash
# Fails if clang-format (with the repository's .clang-format, deal.II's
# style) would change any C++ source or header. Fix with
#   clang-format -i $(find source include tests/unit -name '*.cc' -o -name '*.h')
set -u
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null ||
  { echo "clang-format is not installed (apt-get install clang-format)"; exit 1; }
files=$(find source include tests/unit -name '*.cc' -o -name '*.h' | sort)
status=0
for f in $files; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "$f: not formatted (run clang-format -i $f)"
    status=1
  fi
done
[ "$status" = 0 ] && echo "$(echo "$files" | wc -l) files formatted"
exit $status
