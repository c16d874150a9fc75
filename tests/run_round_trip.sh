#!/bin/bash
# rest_shape.msh is a usable mesh: a forward run that starts from it
# (Mesh/Rest shape file) reaches the target to the error the inverse run
# reported (P1 tetrahedra: the rest shape is exactly the vertex positions).
set -u
exe=$1
out=$2
rm -rf "$out"
common=(--set "Discretization/Polynomial degree=1" --set "Inverse problem/Tolerance=1e-6")
"$exe" "${common[@]}" --set "Output/Directory=$out/inverse" prm/column_inverse.prm >"$out.inverse.log" 2>&1 ||
  { echo "inverse run failed"; tail "$out.inverse.log"; exit 1; }
"$exe" "${common[@]}" --set "Inverse problem/Enabled=false" \
  --set "Mesh/Rest shape file=$out/inverse/rest_shape.msh" \
  --set "Output/Directory=$out/forward" prm/column_inverse.prm >"$out.forward.log" 2>&1 ||
  { echo "forward run from rest_shape.msh failed"; tail "$out.forward.log"; exit 1; }
value() { grep "\"$1\"" "$2" | sed 's/.*: \([^,]*\),*/\1/'; }
reported=$(value mean_error_mm "$out/inverse/summary.json")
reached=$(value mean_error_mm "$out/forward/summary.json")
echo "inverse reported mean error $reported mm; forward from rest_shape.msh: $reached mm"
awk -v a="$reported" -v b="$reached" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d < 1e-6 && b < 1e-5) }' ||
  { echo "FAIL: the rest shape does not reproduce the target"; exit 1; }
echo ok
