#!/bin/bash
# --set overrides reach the run: the effective parameters written to
# parameters.prm hold the overridden values, and the run uses them.
set -u
exe=$1
out=$2
rm -rf "$out"
"$exe" --set "Output/Directory=$out" --set "Discretization/Polynomial degree=1" \
  --set "Materials/Young's modulus=20000" tests/scenes/column_p2_tet.prm >/dev/null || exit 1
grep -q "set Polynomial degree *= 1" "$out/parameters.prm" || { echo "degree not overridden"; exit 1; }
grep -q "set Young's modulus *= 20000" "$out/parameters.prm" || { echo "E not overridden"; exit 1; }
grep -q '"polynomial_degree": 1' "$out/summary.json" || { echo "the run did not use degree 1"; exit 1; }
echo "ok"
