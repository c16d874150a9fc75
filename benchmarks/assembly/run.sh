#!/bin/bash
# Assembly cost in instructions per cell: the forward solve of prm/brain.prm
# under callgrind, collecting only inside ForwardProblem::assemble, split by
# its callers into matrix assemblies (residual and tangent, once per Newton
# step) and residual-only ones (the line search's, the direct inverse's).
# Instruction counts repeat from run to run whatever else the machine does,
# unlike times. The scene's load terms (the follower CSF pressure and the
# elastic support on the surface faces) are part of each assembly.
#
# usage: benchmarks/assembly/run.sh [--coarse]
#   --coarse: P1 only (the version in the tests); fails if a P1 matrix
#   assembly costs more than MAX_MATRIX_PER_CELL instructions per cell,
#   set-up included (18,000: 16,444 now, 17,377 before the follower's
#   and the support's face tangents were shortened and the positions
#   read from the compressed rows, 18,395 before the cells' local
#   indices, 25,344 before fixed DoFs and cell vectors went around
#   AffineConstraints, 47,360 before the cached scatter, the scalar
#   FEValues and the shared face values).
#   Exits 77 (skipped) without valgrind.
# The set-up column: what the first assembly does once per mesh (each
# cell's positions in the matrix, each thread's workspace), divided like
# the rest over the matrix assemblies; "without set-up" is what every
# further assembly costs. The residual's ratio is to that.
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/assembly).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/assembly}
max_matrix_per_cell=${MAX_MATRIX_PER_CELL:-18000}
coarse=false
[ "${1:-}" = --coarse ] && coarse=true
here=$(dirname "$0")
source "$here/../common.sh"
require_valgrind
mkdir -p "$out"
# The function itself: a pattern ending in * would also match its lambdas
# (the copier's, when not inlined) and stop collecting inside them.
assemble='RestShape::ForwardProblem::assemble(RestShape::ForwardProblem::Assemble)'

# configuration: degree:linear solver
configurations=("1:direct")
$coarse || configurations+=("2:cg-amg")

echo "machine: $(machine); one thread, instructions counted by callgrind"
echo
echo "| degree | cells | DoFs | matrix assemblies | instructions per cell | of which set-up | without set-up | residual-only assemblies | instructions per cell | residual / matrix |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for configuration in "${configurations[@]}"; do
  IFS=: read -r degree solver <<<"$configuration"
  base=$out/p$degree
  rm -rf "$base" "$base.callgrind"
  if ! OMP_NUM_THREADS=1 DEAL_II_NUM_THREADS=1 valgrind --tool=callgrind \
    --callgrind-out-file="$base.callgrind" \
    --toggle-collect="$assemble" \
    "$exe" --set "Output/Directory=$base" \
    --set "Discretization/Polynomial degree=$degree" --set "Solver/Linear solver=$solver" \
    --set "Inverse problem/Enabled=false" --set "Scenario/Enabled=false" \
    --set "Output/Write VTU=false" --set "Solver/Check stability=false" \
    prm/brain.prm >"$base.log" 2>&1; then
    echo "| $degree | failed: $(grep -v '^==' "$base.log" | tail -n 1) |"
    status=1
    continue
  fi
  cells=$(sed -n 's/^Cycle 0: \([0-9]*\) cells.*/\1/p' "$base.log")
  dofs=$(value n_dofs "$base/summary.json")
  read -r matrix_calls matrix_ir residual_calls residual_ir <<<"$(
    python3 "$here/calls.py" "$base.callgrind" "$assemble" |
      awk '$3 ~ /residual/ { rc += $1; ri += $2; next } { mc += $1; mi += $2 }
           END { print mc + 0, mi + 0, rc + 0, ri + 0 }')"
  # Set-up once per mesh, done in the first assembly: the cells' positions
  # in the matrix and each thread's workspace.
  setup_ir=$(for f in 'RestShape::TangentScatter::locate(' \
    'RestShape::ForwardProblem::scratch_of_this_thread('; do
    python3 "$here/calls.py" "$base.callgrind" "$f"
  done | awk '{ s += $2 } END { print s + 0 }')
  read -r matrix setup residual <<<"$(awk -v c="$cells" -v mc="$matrix_calls" -v mi="$matrix_ir" \
    -v si="$setup_ir" -v rc="$residual_calls" -v ri="$residual_ir" \
    'BEGIN { printf "%.0f %.0f %.0f\n", mi / mc / c, si / mc / c, (rc > 0 ? ri / rc / c : 0) }')"
  awk -v p="$degree" -v c="$cells" -v d="$dofs" -v mc="$matrix_calls" -v m="$matrix" \
    -v s="$setup" -v rc="$residual_calls" -v r="$residual" 'BEGIN {
      printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %.2f |\n", p, c, d, mc, m, s, m - s, rc, r, r / (m - s) }'
  if $coarse && [ "$matrix" -gt "$max_matrix_per_cell" ]; then
    echo "FAILED: a P1 matrix assembly costs $matrix instructions per cell, more than $max_matrix_per_cell"
    status=1
  fi
done
exit $status
