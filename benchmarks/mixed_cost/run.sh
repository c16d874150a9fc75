#!/bin/bash
# The cost of the mixed formulation on the brain: prm/brain_in_vivo.prm
# (Ogden, bulk modulus 148 kPa, P1 tetrahedra, skull contact; no
# scenario, no VTU, no stability check), four runs in one run of this
# script, one thread each:
#   forward, displacement formulation (locks at nu = 0.4977, for the cost)
#   forward, mixed (the averaged nodal pressure), its tangent split
#   forward, mixed, its tangent assembled (Solver/Nodal pressure product)
#   inverse, mixed (the direct inverse, then the fixed point's check)
# Wall seconds (median of REPEATS) and instructions (callgrind, one run:
# repeatable whatever else the machine does), and the two ratios the
# formulation is held to: the mixed forward solve against the displacement
# one, the mixed inverse against its own forward solve.
#
# usage: benchmarks/mixed_cost/run.sh [--coarse]
#   --coarse: the displacement and the split mixed forward solves under
#   callgrind only (the version in the tests); fails if the mixed one
#   takes more than MAX_FORWARD_RATIO (1.5, what the formulation is held
#   to) times the displacement one's instructions (doc/benchmarks.md,
#   section 13). Exits 77 (skipped) without valgrind.
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/
# mixed_cost), REPEATS (3), REFINEMENTS (0: the scene's mesh; 1: refined
# once, 25,173 DoFs, about 15 minutes under callgrind).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/mixed_cost}
repeats=${REPEATS:-3}
max_forward_ratio=${MAX_FORWARD_RATIO:-1.5}
refinements=${REFINEMENTS:-0}
coarse=false
[ "${1:-}" = --coarse ] && coarse=true
here=$(dirname "$0")
source "$here/../common.sh"
require_valgrind
mkdir -p "$out"
machine_text=$(machine) # before the thread limits: nproc honours OMP_NUM_THREADS
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 DEAL_II_NUM_THREADS=1
prm=prm/brain_in_vivo.prm
# case: name:formulation:inverse:product
cases=("forward_displacement:displacement:false:split" "forward_mixed:mixed:false:split")
$coarse || cases+=("forward_mixed_assembled:mixed:false:assembled" "inverse_mixed:mixed:true:split")

run() { # formulation inverse product directory [launcher...]
  local formulation=$1 inverse=$2 product=$3 directory=$4
  shift 4
  "$@" "$exe" --set "Discretization/Formulation=$formulation" \
    --set "Solver/Nodal pressure product=$product" \
    --set "Inverse problem/Enabled=$inverse" --set "Output/Directory=$directory" \
    --set "Mesh/Global refinements=$refinements" \
    --set "Scenario/Enabled=false" --set "Scenario prone/Enabled=false" \
    --set "Scenario drained/Enabled=false" --set "Scenario craniotomy/Enabled=false" \
    --set "Output/Write VTU=false" --set "Solver/Check stability=false" "$prm"
}
quiet() { "$@" >/dev/null 2>&1; }
instructions() { # callgrind output file: its total Ir
  callgrind_annotate "$1" 2>/dev/null | awk '/PROGRAM TOTALS/ { gsub(/,/, "", $1); print $1 }'
}

echo "machine: $machine_text; one thread each; $prm, $refinements global refinement(s)"
echo
echo "| run | Newton steps | DoFs | wall s | instructions (1e9) |"
echo "| --- | --- | --- | --- | --- |"
declare -A wall ir
status=0
for c in "${cases[@]}"; do
  IFS=: read -r name formulation inverse product <<<"$c"
  base=$out/$name
  rm -rf "$base" "$base.callgrind"
  if ! run "$formulation" "$inverse" "$product" "$base" valgrind --tool=callgrind \
    --callgrind-out-file="$base.callgrind" >"$base.log" 2>&1; then
    echo "| $name | failed: $(grep -v '^==' "$base.log" | tail -n 1) |"
    status=1
    continue
  fi
  ir[$name]=$(instructions "$base.callgrind")
  times=()
  if ! $coarse; then
    for ((r = 0; r < repeats; ++r)); do
      times+=("$(seconds quiet run "$formulation" "$inverse" "$product" "$base.timed")")
    done
  fi
  wall[$name]=$(echo "${times[*]:-0}" | median)
  awk -v n="$name" -v s="$(value newton_iterations "$base/summary.json")" \
    -v d="$(value n_dofs "$base/summary.json")" -v w="${wall[$name]}" -v i="${ir[$name]}" \
    'BEGIN { printf "| %s | %s | %s | %s | %.3f |\n", n, s, d, w, i / 1e9 }'
done
[ $status = 0 ] || exit $status
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f\n", a / b }'; }
forward_ir=$(ratio "${ir[forward_mixed]}" "${ir[forward_displacement]}")
echo
wall_text=
$coarse || wall_text="; wall $(ratio "${wall[forward_mixed]}" "${wall[forward_displacement]}")"
echo "mixed / displacement forward: instructions $forward_ir$wall_text"
if ! $coarse; then
  echo "split / assembled mixed forward: instructions $(ratio "${ir[forward_mixed]}" "${ir[forward_mixed_assembled]}");" \
    "wall $(ratio "${wall[forward_mixed]}" "${wall[forward_mixed_assembled]}")"
  echo "mixed inverse / mixed forward: instructions $(ratio "${ir[inverse_mixed]}" "${ir[forward_mixed]}");" \
    "wall $(ratio "${wall[inverse_mixed]}" "${wall[forward_mixed]}")"
fi
if awk -v r="$forward_ir" -v m="$max_forward_ratio" 'BEGIN { exit !(r > m) }'; then
  echo "FAILED: the mixed forward solve takes $forward_ir times the displacement one's instructions, more than $max_forward_ratio"
  status=1
fi
exit $status
