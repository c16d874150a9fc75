#!/bin/bash
# Scaling benchmark on the brain (prm/brain.prm: CSF, skull contact,
# elastic support): one forward solve and one whole inverse iteration per
# mesh and element, with CG + ML AMG (Solver/Linear solver = cg-amg) and no
# VTU output. Reports DoFs, wall time, time per DoF, Newton iterations,
# AMG-preconditioned CG iterations per Newton step (flat = linear cost),
# peak memory (max RSS by GNU time, summed over the MPI ranks), where the time goes (TimerOutput), and the
# log-log slope of time against DoFs; then the largest forward case on 1 and
# 2 MPI ranks, and on 1 rank with one thread (DEAL_II_NUM_THREADS=1): a single
# rank assembles with one thread per core, two ranks with one thread each,
# so the speed-ups printed at the end separate threads from MPI. Meshes are made by meshes/brain.sh (medium: 6 mm cells, fine:
# 3 mm) into $OUT/meshes.
#
# usage: benchmarks/scaling/run.sh [--coarse]
#   --coarse: the committed coarse mesh, P1, forward only, 1 and 2 ranks
#             (the version run in the tests)
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/scaling),
# CASES ("coarse:1 medium:1 coarse:2 medium+1:1 medium+2:1": mesh:degree,
# where mesh+N refines the mesh N times globally: the same geometry with 8^N
# times the cells), TWO_RANKS (the case run on 1 and 2 ranks; default the
# last of CASES),
# INVERSE (1: also the inverse iteration), SET (one extra 'Section/Parameter=value',
# e.g. 'Contact/Obstacle file=' to measure without contact).
set -u
exe=${RESTSHAPE:-build/restshape}
build=$(dirname "$exe")
out=${OUT:-output/benchmarks/scaling}
cases=${CASES:-coarse:1 medium:1 coarse:2 medium+1:1 medium+2:1}
inverse=${INVERSE:-1}
if [ "${1:-}" = --coarse ]; then
  cases=coarse:1
  inverse=0
fi
mkdir -p "$out/meshes"
mesh_file() {
  if [ "$1" = coarse ]; then
    echo meshes/brain_coarse.msh
  else
    [ -f "$out/meshes/brain_$1.msh" ] ||
      { cp -n meshes/brain_labels.nii.gz "$out/meshes/" && BUILD=$build meshes/brain.sh "$1" "$out/meshes" >/dev/null; }
    echo "$out/meshes/brain_$1.msh"
  fi
}
source "$(dirname "$0")/../common.sh"

run() { # name ranks mesh[+refinements] degree inverse [threads]
  local dir=$out/$1 ranks=$2 launch=() refinements=0
  [[ $3 == *+* ]] && refinements=${3##*+}
  [ -n "${6:-}" ] && launch=(env DEAL_II_NUM_THREADS="$6" OPENBLAS_NUM_THREADS="$6")
  [ "$ranks" -gt 1 ] && launch+=(mpirun --allow-run-as-root --oversubscribe -np "$ranks")
  rm -rf "$dir" "$dir.rss"
  # GNU time around mpirun would report the largest rank's peak, not the
  # sum: each rank appends its own peak (kB) to $dir.rss.
  "${launch[@]}" /usr/bin/time -f "%M" -a -o "$dir.rss" "$exe" --set "Output/Directory=$dir" \
    --set "Mesh/File=${3%+*}" --set "Mesh/Global refinements=$refinements" --set "Discretization/Polynomial degree=$4" \
    --set "Inverse problem/Enabled=$5" --set "Scenario/Enabled=false" \
    --set "Output/Write VTU=false" --set "Solver/Linear solver=cg-amg" \
    ${SET:+--set "$SET"} prm/brain.prm >"$dir.log" 2>&1 || { echo "| $1 | failed: $(tail -n 1 "$dir.log") |"; return 1; }
  local s=$dir/summary.json
  local dofs seconds rss
  dofs=$(value n_dofs "$s")
  rss=$(awk '{ kb += $1 } END { printf "%d", kb / 1024 }' "$dir.rss")
  seconds=$(value wall_seconds "$s")
  # Newton steps: the forward solves', plus the direct inverse's if it ran.
  local newton direct
  newton=$(value newton_iterations "$s")
  direct=$(value direct_inverse_newton_steps "$s")
  [ -n "$direct" ] && newton="$newton + $direct direct"
  echo "$1,$ranks,$dofs,$seconds,$(value newton_iterations "$s"),$(value linear_iterations_per_newton_step "$s"),$rss,$(timer_share Assembly "$dir.log"),$(timer_share 'Linear solve' "$dir.log"),$(timer_share 'Contact search' "$dir.log")" >>"$out/scaling.csv"
  printf '| %s | %s | %s | %.1f | %.2g | %s | %s | %s | %s | %s / %s / %s |\n' "$1" "$ranks" "$dofs" "$seconds" \
    "$(awk -v t="$seconds" -v n="$dofs" 'BEGIN { print 1e6 * t / n }')" "$newton" \
    "$(if [ "$5" = true ]; then echo -; else printf '%.1f' "$(value linear_iterations_per_newton_step "$s")"; fi)" "$rss" \
    "$(value inverse_iterations "$s")" "$(timer_share Assembly "$dir.log")" "$(timer_share 'Linear solve' "$dir.log")" \
    "$(timer_share 'Contact search' "$dir.log")"
}

echo "machine: $(machine)"
echo "run,ranks,n_dofs,seconds,newton_iterations,cg_per_newton,peak_rss_mb,assembly,linear_solve,contact_search" >"$out/scaling.csv"
echo
echo "| run | ranks | DoFs | seconds | microseconds per DoF | Newton iterations | CG iterations per Newton step | peak memory (MB) | inverse iterations | time: assembly / linear solve / contact search |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
status=0
largest=""
mesh_spec() { # level[+N] -> file[+N]
  local file
  file=$(mesh_file "${1%+*}")
  if [[ $1 == *+* ]]; then echo "$file+${1##*+}"; else echo "$file"; fi
}
for c in $cases; do
  level=${c%%:*}
  degree=${c##*:}
  mesh=$(mesh_spec "$level")
  run "forward_${level}_P$degree" 1 "$mesh" "$degree" false || status=1
  largest="$level:$degree"
  if [ "$inverse" = 1 ]; then
    run "inverse_${level}_P$degree" 1 "$mesh" "$degree" true || status=1
  fi
done
largest=${TWO_RANKS:-$largest}
level=${largest%%:*}
degree=${largest##*:}
run "forward_${level}_P${degree}_1thread" 1 "$(mesh_spec "$level")" "$degree" false 1 || status=1
run "forward_${level}_P${degree}_2ranks" 2 "$(mesh_spec "$level")" "$degree" false || status=1
echo
# Memory per rank: each rank's peak against the one-rank run's.
awk -v one="$(awk '{ printf "%d", $1 / 1024 }' "$out/forward_${level}_P${degree}.rss" 2>/dev/null)" \
  '{ peaks = peaks sep sprintf("%d", $1 / 1024); sep = " and " }
   END { printf "peak memory per rank on 2 ranks: %s MB (1 rank: %s MB)\n", peaks, one }' \
  "$out/forward_${level}_P${degree}_2ranks.rss"
awk -F, -v c="forward_${level}_P${degree}" '$1 == c { t2 = $4 } $1 == c "_1thread" { t1 = $4 } $1 == c "_2ranks" { tr = $4 }
  END { if (t1 > 0 && t2 > 0 && tr > 0)
          printf "speed-up over 1 rank with 1 thread: 1 rank with 2 threads %.2fx, 2 ranks %.2fx\n", t1 / t2, t1 / tr }' "$out/scaling.csv"
awk -F, '$1 ~ /^forward/ && $1 !~ /_1thread$/ && $2 == 1 { x[++n] = log($3); y[n] = log($4) }
  END { if (n > 1) { for (i = 1; i <= n; ++i) { sx += x[i]; sy += y[i]; sxx += x[i] * x[i]; sxy += x[i] * y[i] }
        printf "log-log slope of forward time against DoFs: %.2f (%d meshes)\n", (n * sxy - sx * sy) / (n * sxx - sx * sx), n } }' "$out/scaling.csv"
# Parity: one rank, one thread and two ranks reach the same equilibrium.
max_u() { grep -o '"max_displacement_mm": [-0-9.e+]*' "$out/$1/summary.json" | awk '{ print $2 }'; }
c="forward_${level}_P${degree}"
u1=$(max_u "$c") u1t=$(max_u "${c}_1thread") u2=$(max_u "${c}_2ranks")
echo "largest displacement (mm): 1 rank $u1, 1 thread $u1t, 2 ranks $u2"
awk -v a="$u1" -v b="$u1t" -v c="$u2" 'BEGIN { d1 = a - b; d2 = a - c; if (d1 < 0) d1 = -d1; if (d2 < 0) d2 = -d2
  exit (a > 0 && d1 <= 1e-6 * a && d2 <= 1e-6 * a) ? 0 : 1 }' ||
  { echo "FAILED: the runs differ by more than 1e-6 relative"; status=1; }
exit $status
