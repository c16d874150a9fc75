#!/bin/bash
# The block preconditioner of the mixed formulation (Solver/Mixed
# preconditioner = block) against AMG on the condensed tangent
# (condensed), CG in both, as the bulk modulus grows: the Lame shell
# (tests/data/lame_shell.prm: radii 10 and 20 mm, 1 Pa in the cavity, an
# elastic support outside, E = 3 kPa; gmsh mesh of H mm from
# meshes/make_shell.py) with P2-P0 and with P1 and the averaged nodal
# pressure, and prm/brain_in_vivo.prm (Ogden, skull contact; no
# scenario) at P1 and P2: the forward solve from the image, and the
# inverse (the direct inverse, whose GMRES solves the same preconditioner
# serves). One thread each. Each row: Newton steps (of the forward solve;
# of the direct inverse and its Jacobian products), CG iterations per
# forward Newton step (summary.json), wall seconds.
#
# usage: benchmarks/block_preconditioner/run.sh [--coarse]
#   --coarse: the 4 mm shell with P2-P0 at nu = 0.4999 only (the version
#   in the tests); fails unless both converge and the block preconditioner
#   needs fewer than MAX_RATIO (0.6) times the condensed AMG's CG
#   iterations per Newton step.
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/
# block_preconditioner), H (shell mesh size in mm, 2), BRAIN_ONLY (1: the
# brain rows alone).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/block_preconditioner}
h=${H:-2}
max_ratio=${MAX_RATIO:-0.6}
coarse=false
[ "${1:-}" = --coarse ] && coarse=true
$coarse && h=4
here=$(dirname "$0")
source "$here/../common.sh"
mkdir -p "$out"
machine_text=$(machine)
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 DEAL_II_NUM_THREADS=1
mu_brain=670

# run NAME PRECONDITIONER PRM ARGS...: one line of the table.
run() {
  local name=$1 pre=$2 prm=$3
  shift 3
  local dir=$out/$name-$pre
  timed_run "$dir.log" "$exe" --set "Output/Directory=$dir" --set "Solver/Linear solver=cg-amg" \
    --set "Discretization/Formulation=mixed" \
    --set "Solver/Mixed preconditioner=$pre" --set "Solver/Check stability=false" \
    --set "Output/Write VTU=false" --set "Output/Write nodal CSV=false" "$@" "$prm"
  printf '| %s | %s | %s | %s | %s |\n' "$name" "$pre" "$run_code" \
    "$(solve_cells "$dir")" "$run_seconds" | tee -a "$out/table.md"
}
its() { value linear_iterations_per_newton_step "$out/$1/summary.json"; }

: >"$out/table.md"
echo "machine: $machine_text; one thread each" | tee -a "$out/table.md"
echo "| case | preconditioner | exit | Newton steps | direct inverse: Newton steps / Jacobian products | CG iterations per Newton step | wall s |" | tee -a "$out/table.md"
echo "| --- | --- | --- | --- | --- | --- | --- |" | tee -a "$out/table.md"
/usr/bin/python3 meshes/make_shell.py "$out/shell_$h.msh" 10 20 2 "$h" >/dev/null
shell=(--set "Mesh/File=$out/shell_$h.msh")
if $coarse; then
  for pre in block condensed; do
    run shell_P2_nu0.4999 $pre tests/data/lame_shell.prm "${shell[@]}" \
      --set "Discretization/Polynomial degree=2" --set "Materials/Poisson's ratio=0.4999"
  done
  status=0
  for pre in block condensed; do
    grep -q '"converged": true' "$out/shell_P2_nu0.4999-$pre/summary.json" 2>/dev/null ||
      { echo "FAIL: $pre did not converge"; status=1; }
  done
  b=$(its shell_P2_nu0.4999-block) c=$(its shell_P2_nu0.4999-condensed)
  if ! awk -v b="${b:-1e9}" -v c="${c:-0}" -v r="$max_ratio" 'BEGIN { exit !(b < r * c) }'; then
    echo "FAIL: block $b against condensed $c CG iterations per Newton step (ratio at most $max_ratio)"
    status=1
  fi
  exit $status
fi
[ "${BRAIN_ONLY:-}" = 1 ] || for degree in 2 1; do
  for nu in 0.4977 0.4999 0.49999; do
    for pre in block condensed; do
      run "shell_P${degree}_nu$nu" $pre tests/data/lame_shell.prm "${shell[@]}" \
        --set "Discretization/Polynomial degree=$degree" --set "Materials/Poisson's ratio=$nu"
    done
  done
done
for degree in 1 2; do
  for nu in 0.4977 0.4999; do
    K=$(bulk_modulus "$mu_brain" "$nu")
    for inverse in false true; do
      name=brain_P${degree}_forward_nu$nu
      $inverse && name=brain_P${degree}_inverse_nu$nu
      for pre in block condensed; do
        run "$name" $pre prm/brain_in_vivo.prm "${scenario_off[@]}" \
          --set "Discretization/Polynomial degree=$degree" --set "Materials/Bulk modulus=$K" \
          --set "Inverse problem/Enabled=$inverse"
      done
    done
  done
done
