#!/bin/bash
# Benchmark: wall time against error on Hertz contact (prm/hertz.prm: an
# elastic hemisphere, R = 50 mm, E = 10 kPa, nu = 0.3, pressed onto a rigid
# plane by 15 Pa on its flat top). Elements: Q1 and Q2 hexahedra, P1 and P2
# tetrahedra, on hemisphere meshes graded towards the pole made by
# restshape-gridgen at each level (level 0 is meshes/hemisphere_hex.msh;
# each level halves the cells' size with the vertices on the sphere:
# Mesh/Global refinements would keep the coarse facets, a faceted dome whose
# contact is not Hertz's). Each level is a separate run, VTU output off. Hertz with F the computed contact force and
# E* = E / (1 - nu^2): a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2).
# Errors: the contact patch radius (largest distance of an active node from
# the axis through the patch centroid along the contact force) and the
# largest nodal contact pressure, relative to a and p0. Both are nodal
# quantities: the radius can only take node positions, so its error falls
# by steps. Writes $OUT/hertz.csv and prints a markdown table.
#
# usage: benchmarks/time_vs_error/hertz.sh [--coarse]
#   --coarse: Q1 level 0 only (the version run in the tests)
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/time_vs_error),
# LEVELS_Q1 (0 1 2), LEVELS_Q2 (0 1), LEVELS_P1 (0 1 2), LEVELS_P2 (0 1).
set -u
exe=${RESTSHAPE:-build/restshape}
gridgen=$(dirname "$exe")/restshape-gridgen
out=${OUT:-output/benchmarks/time_vs_error}
declare -A levels=([Q1]=${LEVELS_Q1:-0 1 2} [Q2]=${LEVELS_Q2:-0 1}
                   [P1]=${LEVELS_P1:-0 1 2} [P2]=${LEVELS_P2:-0 1})
elements="Q1 Q2 P1 P2"
if [ "${1:-}" = --coarse ]; then
  levels=([Q1]=0)
  elements=Q1
fi
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

csv=$out/hertz.csv
echo "scene: prm/hertz.prm; machine: $(machine)"
start_table "$csv" element,level,n_cells,n_dofs,seconds,force_N,radius_mm,hertz_radius_mm,radius_error,max_pressure_Pa,hertz_pressure_Pa,pressure_error,newton_iterations \
  element level cells DoFs seconds "F (N)" "radius (mm)" "Hertz a (mm)" "radius error" \
  "peak pressure (Pa)" "Hertz p0 (Pa)" "pressure error" "Newton iterations"
status=0
for element in $elements; do
  degree=${element:1:1}
  cells=hexahedra
  [[ $element == P* ]] && cells=tetrahedra
  for level in ${levels[$element]}; do
    dir=$out/hertz_${element}_$level
    mesh=$out/hemisphere_${cells}_$level.msh
    [ -f "$mesh" ] || "$gridgen" --hemisphere 50 --refinements $((2 + level)) --grading 2 \
      --cell-type "$cells" --out "$mesh" >/dev/null || { status=1; continue; }
    if ! "$exe" --set "Output/Directory=$dir" --set "Output/Write VTU=false" \
      --set "Mesh/File=$mesh" --set "Mesh/Cell type=$cells" \
      --set "Discretization/Polynomial degree=$degree" prm/hertz.prm >"$dir.log" 2>&1; then
      echo "| $element | $level | failed: $(tail -n 1 "$dir.log") |"
      status=1
      continue
    fi
    s=$dir/summary.json
    # F is the z component of contact_force_N.
    force=$(grep '"contact_force_N"' "$s" | sed 's/.*\[[^,]*, *[^,]*, *\([^]]*\)\].*/\1/')
    row=$(awk -v e="$element" -v l="$level" -v c="$(value n_cells "$s")" -v n="$(value n_dofs "$s")" \
      -v t="$(value wall_seconds "$s")" -v F="$force" -v a="$(value contact_patch_radius_mm "$s")" \
      -v p="$(value contact_pressure_max_Pa "$s")" -v it="$(value newton_iterations "$s")" 'BEGIN {
        R = 0.05; Es = 10000 / (1 - 0.09); pi = atan2(0, -1)
        ah = (3 * F * R / (4 * Es)) ^ (1 / 3); ph = 3 * F / (2 * pi * ah * ah)
        printf "%s,%s,%s,%s,%.3g,%.5f,%.3f,%.3f,%.3f,%.0f,%.0f,%.3f,%s", e, l, c, n, t, F,
          a, ah * 1e3, (a - ah * 1e3) / (ah * 1e3), p, ph, (p - ph) / ph, it }')
    echo "$row" >>"$csv"
    echo "| ${row//,/ | } |"
  done
done
# Hertz: every contact radius within 5 % of Hertz's a (node spacing
# limits it), every peak pressure within 20 % of p0.
awk -F, 'NR > 1 { r = $9 < 0 ? -$9 : $9; p = $12 < 0 ? -$12 : $12
    if (r > 0.05 || p > 0.2) { bad = 1; print "FAILED: " $1 " level " $2 ": radius error " $9 ", pressure error " $12 } }
  END { exit bad }' "$csv" || status=1
exit $status
