#!/bin/bash
# How far the averaged nodal pressure tetrahedron (P1, Discretization/
# Formulation = mixed) converges as Poisson's ratio nears 0.5: the Lame
# shell (tests/data/lame_shell.prm: radii 10 and 20 mm, 1 Pa in the
# cavity, an elastic support outside, E = 3 kPa) on gmsh meshes of 4 to
# 1.4 mm (meshes/make_shell.py), the RMS error of the radial displacement
# against the closed form (tests/check_lame_shell.py) for P1 displacement
# at nu = 0.3 (the reference) and P1 mixed at several ratios, with the
# rate of each pair of meshes against h ~ nodes^(-1/3). One table in
# markdown, the runs' CSV in $OUT/rates.csv.
#
# usage: benchmarks/nodal_pressure_rates/run.sh [--coarse]
#   --coarse: the 2.8 and 2 mm meshes at nu = 0.4977 only (the test's
#   version); fails unless P1 mixed at 0.4977 is at most as far off as
#   P1 displacement at 0.3 on the 2 mm mesh and converges at that one's
#   rate (within 0.35). The Bonet-Burton form (BOUNDARY=own) fails it.
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/
# nodal_pressure_rates), BOUNDARY (Discretization/Nodal pressure at the
# boundary for the mixed runs: interior, the default, or own, which gives
# the other table of doc/benchmarks.md section 17).
set -eu -o pipefail
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/nodal_pressure_rates}
here=$(dirname "$0")
source "$here/../common.sh"
sizes=(4 2.8 2 1.6 1.4)
ratios=(0.3 0.45 0.49 0.4977 0.4999)
boundary=${BOUNDARY:-interior}
coarse=false
if [ "${1:-}" = --coarse ]; then
  coarse=true
  sizes=(2.8 2)
  ratios=(0.4977)
fi
rm -rf "$out"
mkdir -p "$out"
for h in "${sizes[@]}"; do
  /usr/bin/python3 meshes/make_shell.py "$out/shell_$h.msh" 10 20 2 "$h"
done

# error FORMULATION NU H: "RMS_PERCENT NODES SECONDS" of one run.
error() {
  local name=$1_$2_$3 figure seconds_taken
  "$exe" --set "Output/Directory=$out/$name" \
    --set "Mesh/File=$out/shell_$3.msh" --set "Discretization/Formulation=$1" \
    --set "Materials/Poisson's ratio=$2" --set "Solver/Check stability=false" \
    --set "Discretization/Nodal pressure at the boundary=$boundary" \
    tests/data/lame_shell.prm >"$out/$name.log" 2>&1 ||
    { echo "FAIL: $name did not run (see $out/$name.log)" >&2; exit 1; }
  seconds_taken=$(value wall_seconds "$out/$name/summary.json")
  figure=$(/usr/bin/python3 tests/check_lame_shell.py "$out/$name/nodes.csv" --E 3000 \
    --nu "$2" --p-inner 1 --support 1e3 --label "$name" |
    sed -E 's/.*displacement ([0-9.]+) %.*/\1/')
  echo "$figure $(value n_nodes "$out/$name/summary.json") $seconds_taken"
}

echo "machine: $(machine); tests/data/lame_shell.prm, meshes of ${sizes[*]} mm; nodal pressure at the boundary: $boundary"
header="| element | nu |"
rule="| --- | --- |"
for h in "${sizes[@]}"; do
  header+=" $h mm |"
  rule+=" --- |"
done
printf '\n%s rate (last pair) |\n%s --- |\n' "$header" "$rule"
echo "formulation,nu,h_mm,nodes,rms_percent,seconds" >"$out/rates.csv"
declare -A errors rates
for c in displacement:0.3 $(printf 'mixed:%s ' "${ratios[@]}"); do
  IFS=: read -r formulation nu <<<"$c"
  line="| P1 $formulation | $nu |"
  previous=""
  for h in "${sizes[@]}"; do
    read -r e n s < <(error "$formulation" "$nu" "$h")
    echo "$formulation,$nu,$h,$n,$e,$s" >>"$out/rates.csv"
    errors[$formulation:$nu:$h]=$e
    line+=" $e |"
    if [ -n "$previous" ]; then
      rate=$(awk -v a="$previous" -v e="$e" -v n="$n" 'BEGIN { split(a, p, " ")
        printf "%.2f", log(p[1] / e) / (log(n / p[2]) / 3) }')
    fi
    previous="$e $n"
  done
  rates[$formulation:$nu]=$rate
  echo "$line $rate |"
done
if $coarse; then
  e=${errors[mixed:0.4977:2]} e0=${errors[displacement:0.3:2]}
  r=${rates[mixed:0.4977]} r0=${rates[displacement:0.3]}
  if awk -v e="$e" -v e0="$e0" -v r="$r" -v r0="$r0" \
    'BEGIN { exit !(e <= e0 && r >= r0 - 0.35 && r <= r0 + 0.35) }'; then
    echo "ok: P1 mixed at nu = 0.4977 on 2 mm: $e % (P1 displacement at 0.3: $e0 %), rate $r ($r0)"
  else
    echo "FAIL: P1 mixed at nu = 0.4977 on 2 mm: $e % against $e0 % for P1 displacement at 0.3, rate $r against $r0"
    exit 1
  fi
fi
