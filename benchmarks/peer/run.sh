#!/bin/bash
# Against the peer: the cantilever's forward solve (prm/cantilever.prm: 100
# x 10 x 10 mm, the first 10 mm clamped, its own weight, E = 100 kPa, P2
# tetrahedra) in RestShape and in CalculiX 2.20 (*STATIC with NLGEOM,
# C3D10 on the same mesh: the same nodes and DoFs; St. Venant-Kirchhoff,
# which CalculiX uses for *ELASTIC at large deformation), in the same run of
# this script, each on one thread, REPEATS times (the median is printed).
# Both programs run as their users run them: their default tolerances
# (ours: |R|/|f| <= 1e-10; CalculiX accepts an increment at a residual of
# 0.5 % of the mean force, about 3e-5 off equilibrium here) and, in
# RestShape, no VTU and no stability check (CalculiX does neither) and
# MUMPS's LDL^T (Solver/Direct factorisation = ldlt). The
# tip deflections differ by the difference between the two laws.
#
# usage: benchmarks/peer/run.sh [--coarse]
#   --coarse: the 20 x 2 x 2 mesh only (the version in the tests). It
#   fails if RestShape needs more than MAX_NEWTON_STEPS (8) Newton steps,
#   or, where CalculiX is installed, if the two largest displacements
#   differ by more than MAX_LAW_DIFFERENCE (1 %). It does not install
#   CalculiX; the full run does (apt-get, as root), when it is missing.
# Environment: RESTSHAPE (build/restshape), GRIDGEN (build/restshape-gridgen),
# OUT (output/benchmarks/peer), REPEATS (3; 1 with --coarse), PYTHON
# (/usr/bin/python3, with meshio), MESHES (the subdivisions to run,
# "40,4,4 80,8,8": 19,683 and 139,587 DoFs).
set -u
exe=${RESTSHAPE:-build/restshape}
gridgen=${GRIDGEN:-build/restshape-gridgen}
out=${OUT:-output/benchmarks/peer}
python=${PYTHON:-/usr/bin/python3}
max_newton_steps=${MAX_NEWTON_STEPS:-8}
max_law_difference=${MAX_LAW_DIFFERENCE:-1}
here=$(dirname "$0")
source "$here/../common.sh"
coarse=false
[ "${1:-}" = --coarse ] && coarse=true
repeats=${REPEATS:-3}
$coarse && repeats=${REPEATS:-1}
# Subdivisions of the 100 x 10 x 10 mm box (six tetrahedra per hexahedron).
read -r -a meshes <<<"${MESHES:-40,4,4 80,8,8}"
$coarse && meshes=("20,2,2")
machine_text=$(machine)
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$out"

if ! command -v ccx >/dev/null; then
  if ! $coarse && [ "$(id -u)" = 0 ]; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
      calculix-ccx >"$out/apt.log" 2>&1 || { echo "cannot install calculix-ccx: see $out/apt.log"; exit 1; }
  fi
fi
have_ccx=false
command -v ccx >/dev/null && have_ccx=true


ours() { # mesh directory
  "$exe" --set "Mesh/File=$1" --set "Output/Directory=$2" \
    --set "Output/Write VTU=false" --set "Adaptive refinement/Cycles=0" \
    --set "Solver/Check stability=false" --set "Solver/Direct factorisation=ldlt" \
    prm/cantilever.prm >"$2.log" 2>&1
}
theirs() { # job (directory/name, without .inp)
  (cd "$(dirname "$1")" && ccx -i "$(basename "$1")" >"$(basename "$1").log" 2>&1) &&
    grep -q "Job finished" "$1.log"
}
# The largest displacement magnitude (mm) in CalculiX's .dat (metres).
their_largest() {
  awk 'NF == 4 && $1 ~ /^[0-9]+$/ { m = sqrt($2 * $2 + $3 * $3 + $4 * $4); if (m > max) max = m }
       END { printf "%.4f\n", 1000 * max }' "$1"
}

echo "machine: $machine_text; one thread each"
echo
echo "| subdivisions | DoFs | RestShape Newton steps | RestShape s | CalculiX increments / iterations | CalculiX s | CalculiX / RestShape | largest displacement RestShape / CalculiX (mm) | difference |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for subdivisions in "${meshes[@]}"; do
  name=cantilever_$(echo "$subdivisions" | tr , x)
  base=$out/$name
  "$gridgen" --size 100,10,10 --subdivisions "$subdivisions" --slab x:0:10:2 \
    --out "$base.msh" >/dev/null || { echo "| $subdivisions | mesh failed |"; exit 1; }
  our_times=() their_times=()
  for ((r = 0; r < repeats; ++r)); do
    t=$(seconds ours "$base.msh" "$base.ours") ||
      { echo "| $subdivisions | RestShape failed: $(tail -n 1 "$base.ours.log") |"; exit 1; }
    our_times+=("$t")
  done
  summary=$base.ours/summary.json
  steps=$(value newton_iterations "$summary")
  dofs=$(value n_dofs "$summary")
  ours_max=$(value max_displacement_mm "$summary")
  if $have_ccx; then
    "$python" "$here/msh_to_inp.py" "$base.msh" "$base.inp" 2 >/dev/null ||
      { echo "| $subdivisions | the CalculiX input could not be written |"; exit 1; }
    for ((r = 0; r < repeats; ++r)); do
      t=$(seconds theirs "$base") ||
        { echo "| $subdivisions | CalculiX failed: $(tail -n 3 "$base.log" | tr '\n' ' ') |"; exit 1; }
      their_times+=("$t")
    done
    increments=$(grep -c "^ increment .* attempt" "$base.log")
    iterations=$(grep -c "^ iteration" "$base.log")
    theirs_max=$(their_largest "$base.dat")
    ours_s=$(echo "${our_times[*]}" | median)
    theirs_s=$(echo "${their_times[*]}" | median)
    read -r ratio difference <<<"$(awk -v a="$ours_s" -v b="$theirs_s" -v u="$ours_max" -v v="$theirs_max" \
      'BEGIN { printf "%.2f %.2f\n", b / a, 100 * (u - v) / v }')"
    echo "| $subdivisions | $dofs | $steps | $ours_s | $increments / $iterations | $theirs_s | $ratio | $ours_max / $theirs_max | $difference % |"
    awk -v d="$difference" -v m="$max_law_difference" 'BEGIN { exit !(d > m || -d > m) }' &&
      { echo "the largest displacements differ by more than $max_law_difference %"; status=1; }
  else
    echo "| $subdivisions | $dofs | $steps | $(echo "${our_times[*]}" | median) | CalculiX is not installed | | | $ours_max / - | |"
  fi
  if $coarse && [ "$steps" -gt "$max_newton_steps" ]; then
    echo "RestShape took $steps Newton steps, more than $max_newton_steps"
    status=1
  fi
done
exit $status
