#!/bin/bash
# One case of tests/error_cases.txt (bad input): the line of NAME, whose
# fields are separated by ' | ': NAME | EXIT CODE | expected message |
# ARGUMENT | ARGUMENT ..., run by run_error.sh.
#
# usage: run_error_case.sh RESTSHAPE OUTPUT_DIRECTORY CASES_FILE NAME
set -u
here=$(cd "$(dirname "$0")" && pwd)
line=$(grep -m1 -E "^$4 \| " "$3") || { echo "no case '$4' in $3"; exit 1; }
fields=()
rest=$line
while [[ $rest == *" | "* ]]; do
  fields+=("${rest%% | *}")
  rest=${rest#* | }
done
fields+=("$rest")
exec "$here/run_error.sh" "$1" "$2" "${fields[1]}" "${fields[2]}" "${fields[@]:3}"
