#!/bin/bash
# Where the refined brains get hard: the forward brain scene without contact
# (prm/brain.prm, P1, no inverse) on ever finer meshes, with VTU, and per
# mesh the smallest cell volume ratio J = det F and the largest von Mises
# stress (benchmarks/scaling/cell_volume.py) and the residual after the
# first (linear-elastic) Newton step. If these grow without bound under
# refinement, the scene has a stress singularity (here: where the
# pressure-loaded, compressed cerebrum meets the clamped cerebellum and
# brainstem).
#
# usage: benchmarks/scaling/singularity.sh
# Environment: RESTSHAPE (build/restshape), OUT
# (output/benchmarks/singularity), LEVELS ("coarse coarse+1 medium
# coarse+2 medium+1": mesh[+global refinements]; medium is made by
# meshes/brain.sh). Needs python3 with numpy.
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/singularity}
levels=${LEVELS:-coarse coarse+1 medium coarse+2 medium+1}
python=/usr/bin/python3
[ -x $python ] || python=python3
mkdir -p "$out/meshes"
source "$(dirname "$0")/../common.sh"
echo "machine: $(machine)"
echo
echo "| mesh | DoFs | Newton iterations | residual after step 1 | cells | smallest J | 1st percentile J | largest von Mises (Pa) | most compressed cell at (mm) |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
for level in $levels; do
  base=${level%+*}
  refinements=0
  [[ $level == *+* ]] && refinements=${level##*+}
  if [ "$base" = coarse ]; then
    mesh=meshes/brain_coarse.msh
  else
    mesh=$out/meshes/brain_$base.msh
    [ -f "$mesh" ] || { cp -n meshes/brain_labels.nii.gz "$out/meshes/" &&
      BUILD=$(dirname "$exe") meshes/brain.sh "$base" "$out/meshes" >/dev/null; }
  fi
  dir=$out/$level
  rm -rf "$dir"
  if ! "$exe" --set "Output/Directory=$dir" --set "Mesh/File=$mesh" \
    --set "Mesh/Global refinements=$refinements" --set "Contact/Obstacle file=" \
    --set "Inverse problem/Enabled=false" --set "Scenario/Enabled=false" \
    --set "Solver/Linear solver=cg-amg" prm/brain.prm >"$dir.log" 2>&1; then
    echo "| $level | failed: $(tail -n 1 "$dir.log") |"
    status=1
    continue
  fi
  first=$(grep -m1 "Newton  1:" "$dir.log" | sed 's/.*-> *\([0-9.e+-]*\),.*/\1/')
  stats=$($python "$(dirname "$0")/cell_volume.py" "$dir/solution-0000.vtu" 1)
  echo "$stats" | awk -v l="$level" -v n="$(value n_dofs "$dir/summary.json")" \
    -v it="$(value newton_iterations "$dir/summary.json")" -v r="$first" '
    NR == 1 { gsub(/,|;/, ""); cells = $2; jmin = $5; j1 = $7; vm = $13 }
    NR == 2 { where = $4 " " $5 " " $6; gsub(/,$/, "", where) }
    END { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", l, n, it, r, cells, jmin, j1, vm, where }'
done
exit $status
