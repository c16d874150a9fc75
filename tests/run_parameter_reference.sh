#!/bin/bash
# The manual's parameter reference (doc/parameters.md) is what the program
# says: the reference generated from RESTSHAPE against the committed file
# (git's HEAD in a checkout: the build rewrites the working copy, so only a
# committed reference that is current passes; the file itself elsewhere).
#
# usage: run_parameter_reference.sh RESTSHAPE
set -u
cd "$(dirname "$0")/.."
generated=$(mktemp)
trap 'rm -f "$generated"' EXIT
doc/make_parameter_reference.sh "$1" >"$generated" || exit 1
if git rev-parse --is-inside-work-tree >/dev/null 2>&1 &&
  git cat-file -e HEAD:doc/parameters.md 2>/dev/null; then
  committed=$(mktemp)
  trap 'rm -f "$generated" "$committed"' EXIT
  git show HEAD:doc/parameters.md >"$committed"
else
  committed=doc/parameters.md
fi
if ! diff -u "$committed" "$generated"; then
  echo "doc/parameters.md is not current: build, then commit doc/parameters.md"
  exit 1
fi
echo current
