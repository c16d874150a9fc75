#!/bin/bash
# Benchmark: time against error at the brain's in vivo Poisson's ratio
# (0.4977), every element with both formulations, on the Lame shell
# (tests/data/lame_shell.prm: radii 10 and 20 mm, 1 Pa in the cavity, an
# elastic support outside; the closed form u(r) = A r + B / r^2 gives the
# exact error, tests/check_lame_shell.py). Tetrahedra from
# meshes/make_shell.py, hexahedra from meshes/make_shell_hex.py (a cubed
# sphere), at several cell sizes. Q2 mixed is Q2-P1disc (Cell pressure =
# linear), Q1 mixed Q1-P0. Each run is a whole forward solve, set-up
# included, VTU and the stability check off. On this shell (no fixed label)
# `Linear solver = auto` takes the direct solver. Writes $OUT/mixed_time_vs_error.csv (element,
# formulation, cell size, cells, DoFs, seconds, RMS error %, error x DoFs,
# error x seconds) and prints a markdown table.
#
# usage: benchmarks/mixed_time_vs_error/run.sh [--coarse]
#   --coarse: P1 both formulations on the 4 mm mesh (the version run in the
#   tests); fails unless the mixed element's error is below a third of the
#   locking displacement element's.
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/mixed_time_vs_error),
# NU (0.4977), SIZES_P1 (4 2.8 2 1.6), SIZES_P2 (4 2.8 2), SIZES_Q1 (4 2.8 2),
# SIZES_Q2 (4 2.8 2).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/mixed_time_vs_error}
nu=${NU:-0.4977}
here=$(cd "$(dirname "$0")" && pwd)
declare -A sizes=([P1]=${SIZES_P1:-4 2.8 2 1.6} [P2]=${SIZES_P2:-4 2.8 2}
                  [Q1]=${SIZES_Q1:-4 2.8 2} [Q2]=${SIZES_Q2:-4 2.8 2})
elements="P1 P2 Q1 Q2"
if [ "${1:-}" = --coarse ]; then
  sizes=([P1]=4)
  elements=P1
fi
mkdir -p "$out"
source "$here/../common.sh"

csv=$out/mixed_time_vs_error.csv
echo "scene: tests/data/lame_shell.prm, nu = $nu; machine: $(machine)"
start_table "$csv" element,formulation,cell_size_mm,n_cells,n_dofs,seconds,rms_error_percent,error_x_dofs,error_x_seconds \
  element formulation "cell size (mm)" cells DoFs seconds "RMS error (%)" "error x DoFs" "error x seconds"
status=0
for element in $elements; do
  case $element in
  P*) cells=tetrahedra generator=meshes/make_shell.py ;;
  Q*) cells=hexahedra generator=meshes/make_shell_hex.py ;;
  esac
  pressure=auto
  [ "$element" = Q2 ] && pressure=linear
  degree=${element:1:1}
  for h in ${sizes[$element]}; do
    mesh=$out/shell_${cells}_$h.msh
    [ -f "$mesh" ] || /usr/bin/python3 "$generator" "$mesh" 10 20 2 "$h"
    for formulation in displacement mixed; do
      dir=$out/${element}_${formulation}_$h
      rm -rf "$dir"
      if ! "$exe" --set "Output/Directory=$dir" --set "Mesh/File=$mesh" \
        --set "Mesh/Cell type=$cells" --set "Discretization/Polynomial degree=$degree" \
        --set "Discretization/Formulation=$formulation" --set "Solver/Check stability=false" \
        --set "Discretization/Cell pressure=$pressure" \
        --set "Materials/Poisson's ratio=$nu" tests/data/lame_shell.prm >"$dir.log" 2>&1; then
        echo "| $element | $formulation | $h | failed: $(tail -n 1 "$dir.log") |"
        status=1
        continue
      fi
      s=$dir/summary.json
      error=$(/usr/bin/python3 tests/check_lame_shell.py "$dir/nodes.csv" --E 3000 --nu "$nu" \
        --p-inner 1 --support 1e3 --tolerance 10 --label x |
        sed -E 's/.*displacement ([0-9.]+) %.*/\1/')
      dofs=$(value n_dofs "$s") seconds=$(value wall_seconds "$s")
      row="$element,$formulation,$h,$(value n_cells "$s"),$dofs,$(printf %.3g "$seconds"),$error,$(awk -v e="$error" -v n="$dofs" 'BEGIN { printf "%.3g", e * n }'),$(awk -v e="$error" -v t="$seconds" 'BEGIN { printf "%.3g", e * t }')"
      echo "$row" >>"$csv"
      echo "| ${row//,/ | } |"
    done
  done
done
# The figure the coarse version asserts: P1 on the 4 mm mesh, the mixed
# element's error below a third of the displacement element's (measured
# 12.4 % against 71 %).
awk -F, '$1 == "P1" && $3 == 4 { e[$2] = $7 }
  END { if (!("mixed" in e) || !("displacement" in e)) exit 1
        printf "P1 at 4 mm: mixed %.3g %%, displacement %.3g %%\n", e["mixed"], e["displacement"]
        exit !(3 * e["mixed"] < e["displacement"]) }' "$csv" ||
  { echo "FAIL: the mixed P1 element is not 3 times as accurate as the displacement one"; status=1; }
exit $status
