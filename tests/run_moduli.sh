#!/bin/bash
# Materials/Shear modulus and Bulk modulus against Young's modulus and
# Poisson's ratio: prm/column.prm (E = 10 kPa, nu = 0) given as mu = 5 kPa,
# K = 10/3 kPa, and as E with K, must give the same nodes (nodes.csv to
# 1e-9), and the screen must say the formulation the ratio implies.
#
# usage: run_moduli.sh RESTSHAPE OUTPUT_DIRECTORY
set -u
exe=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
common=(--set "Output/Write VTU=false" --set "Output/Write nodal CSV=true")
run() {
  local name=$1
  shift
  "$exe" "${common[@]}" --set "Output/Directory=$out/$name" "$@" prm/column.prm >"$out/$name.log" 2>&1 ||
    { echo "FAIL: the $name run failed"; tail -n 5 "$out/$name.log"; exit 1; }
}
run e_nu
run mu_k --set "Materials/Shear modulus=5000" --set "Materials/Bulk modulus=3333.3333333333333"
run e_k --set "Materials/Bulk modulus=3333.3333333333333"
for name in mu_k e_k; do
  numdiff -q -s ', \n' -a 1e-12 -r 1e-9 "$out/e_nu/nodes.csv" "$out/$name/nodes.csv" ||
    { echo "FAIL: $name differs from E and nu"; exit 1; }
done
echo "ok: shear and bulk modulus, and E with the bulk modulus, give E and nu's nodes"
