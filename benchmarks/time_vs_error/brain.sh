#!/bin/bash
# Benchmark: wall time against error on the brain (prm/brain.prm, one
# forward solve from the image geometry, no inverse iteration), against a
# much finer reference on the same geometry: the committed coarse mesh
# refined globally (Mesh/Global refinements), so every run has the coarse
# mesh's vertices as nodes and the displacements are compared there, node
# by node, without interpolation (Output/Write nodal CSV).
# Error: root mean square over the coarse vertices of |u - u_ref| (mm), its
# maximum, the RMS relative to the RMS of |u_ref|, and the total potential
# energy (J; of two equilibria the lower is preferred, doc/model.md). Cases are
# element:level, tetrahedra for P, hexahedra (each tetrahedron split into
# four) for Q; the reference is a case of its own. An element name ending
# in m (P1m, P2m, Q1m) is the mixed formulation, else the displacement one
# (Discretization/Formulation). Without SET the scene is as in PRM
# (prm/brain.prm: skull contact, CSF pressure, elastic support).
# Adaptive cases (hexahedra only): level aNk or aNt, N cycles refining 30 %
# of the cells (Adaptive refinement/Refine fraction) by Kelly's indicator
# (k) or the traction jump (t); the seconds are those of all N + 1 solves.
# A trailing r (aNkr) restarts every cycle from the unloaded mesh
# (Adaptive refinement/Transfer solution = false) instead of from the
# previous cycle's solution.
#
# usage: benchmarks/time_vs_error/brain.sh [--coarse]
#   --coarse: P1 level 0 against P1 level 1 (the version run in the tests)
# Environment: RESTSHAPE (build/restshape), OUT (output/benchmarks/time_vs_error),
# CASES ("P1:0 P1:1 P1:2 P2:0 P2:1 Q1:0"), REFERENCE (P2:2), PRM
# (prm/brain.prm; prm/brain_in_vivo.prm needs its scenarios off in SET),
# SET (extra 'Section/Parameter=value' settings separated by '|', e.g.
# 'Contact/Obstacle file=|Solver/Tangent shift=1e-3'), MESH (the coarse mesh,
# meshes/brain_coarse.msh; another one, e.g. made with restshape-mesh
# --close-sulci, is used by every case and its vertices are compared).
set -u
exe=${RESTSHAPE:-build/restshape}
out=${OUT:-output/benchmarks/time_vs_error}/brain
cases=${CASES:-P1:0 P1:1 P1:2 P2:0 P2:1 Q1:0}
reference=${REFERENCE:-P2:2}
mesh=${MESH:-meshes/brain_coarse.msh}
prm=${PRM:-prm/brain.prm}
if [ "${1:-}" = --coarse ]; then
  cases=P1:0
  reference=P1:1
fi
mkdir -p "$out"
source "$(dirname "$0")/../common.sh"

run() { # element:level
  local element=${1%%:*} level=${1##*:} cells=tetrahedra formulation=displacement
  [[ $element == Q* ]] && cells=hexahedra
  [[ $element == *m ]] && formulation=mixed
  local dir=$out/${element}_$level
  local refine=(--set "Mesh/Global refinements=$level")
  if [[ $level == a* ]]; then # aNk / aNt: N adaptive cycles, Kelly / traction jump
    local estimator=kelly
    [ "${level:2:1}" = t ] && estimator="traction jump"
    local transfer=true
    [ "${level:3:1}" = r ] && transfer=false
    refine=(--set "Adaptive refinement/Strategy=adaptive" --set "Adaptive refinement/Cycles=${level:1:1}"
      --set "Adaptive refinement/Estimator=$estimator" --set "Adaptive refinement/Transfer solution=$transfer")
  fi
  local extra=() setting
  if [ -n "${SET:-}" ]; then
    IFS='|' read -ra settings <<<"$SET"
    for setting in "${settings[@]}"; do extra+=(--set "$setting"); done
  fi
  rm -rf "$dir"
  "$exe" --set "Output/Directory=$dir" --set "Output/Write VTU=false" --set "Output/Write nodal CSV=true" \
    --set "Inverse problem/Enabled=false" --set "Scenario/Enabled=false" \
    --set "Solver/Linear solver=cg-amg" --set "Mesh/Cell type=$cells" \
    --set "Discretization/Polynomial degree=${element:1:1}" --set "Mesh/File=$mesh" "${refine[@]}" \
    --set "Discretization/Formulation=$formulation" "${extra[@]}" "$prm" >"$dir.log" 2>&1 ||
    { echo "| $element | $level | failed: $(tail -n 1 "$dir.log") |"; return 1; }
}

echo "scene: $prm on $mesh${SET:+ with $SET}, forward; reference $reference; machine: $(machine)"
status=0
run "$reference" || exit 1
for c in $cases; do
  run "$c" || status=1
done
echo
python3 - "$out" "$reference" "$mesh" $cases <<'PY' || status=1
import csv, json, math, sys
out, reference, mesh, cases = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
def load(case):
    d = f"{out}/{case.replace(':', '_')}"
    nodes = {}
    for r in csv.DictReader(open(f"{d}/nodes.csv")):
        key = tuple(round(float(r[k]), 4) for k in ('x_mm', 'y_mm', 'z_mm'))
        nodes[key] = [float(r[k]) for k in ('u_x_mm', 'u_y_mm', 'u_z_mm')]
    summary = json.load(open(f"{d}/summary.json"))
    # Newton iterations of every cycle ("6 + 21"), from convergence.csv.
    cycles = [r['newton_iterations'] for r in csv.DictReader(open(f"{d}/convergence.csv"))]
    summary['newton_iterations'] = ' + '.join(cycles)
    return nodes, summary
# The coarse mesh's vertices: the nodes of the gmsh 2 file.
vertices = []
with open(mesh) as f:
    lines = f.read().split('\n')
i = lines.index('$Nodes')
if not lines[1].startswith('2.'):
    raise SystemExit(f'{mesh}: expected a gmsh 2 file')
n = int(lines[i + 1])
for line in lines[i + 2:i + 2 + n]:
    x = line.split()[1:4]
    vertices.append(tuple(round(float(v), 4) for v in x))
ref, ref_summary = load(reference)
def match(nodes):
    # Coordinates rounded to 1e-4 mm; one that rounds the other way after
    # the round trip through the CSV is matched to the nearest node.
    for v in vertices:
        if v not in nodes:
            near = min(nodes, key=lambda k: math.dist(k, v))
            if math.dist(near, v) > 1e-3:
                raise SystemExit(f"coarse vertex {v} not found among the nodes")
            nodes[v] = nodes[near]
match(ref)
ref_rms = math.sqrt(sum(sum(c * c for c in ref[v]) for v in vertices) / len(vertices))
rows = [('element', 'level', 'n_dofs', 'seconds', 'newton_iterations', 'rms_error_mm', 'max_error_mm', 'relative_rms_error',
         'potential_energy_J')]
print(f"reference {reference}: {ref_summary['n_dofs']} DoFs, {ref_summary['wall_seconds']:.1f} s, "
      f"RMS displacement at the {len(vertices)} coarse vertices {ref_rms:.4f} mm, "
      f"potential energy {ref_summary['potential_energy_J']:.6g} J")
print()
print('| element | level | DoFs | seconds | Newton iterations | RMS error (mm) | max error (mm) | relative RMS error | potential energy (J) |')
print('| --- | --- | --- | --- | --- | --- | --- | --- | --- |')
for case in cases:
    try:
        nodes, s = load(case)
    except OSError:
        continue
    match(nodes)
    e = [math.dist(nodes[v], ref[v]) for v in vertices]
    rms = math.sqrt(sum(x * x for x in e) / len(e))
    element, level = case.split(':')
    energy = s['potential_energy_J']
    rows.append((element, level, s['n_dofs'], s['wall_seconds'], s['newton_iterations'], rms, max(e), rms / ref_rms,
                 energy))
    print(f"| {element} | {level} | {s['n_dofs']} | {s['wall_seconds']:.1f} | {s['newton_iterations']} | "
          f"{rms:.3g} | {max(e):.3g} | {rms / ref_rms:.3g} | {energy:.6g} |")
with open(f"{out}/brain.csv", 'w') as f:
    csv.writer(f).writerows(rows)
PY
# Every case within half the reference's RMS displacement of it, and not
# equal to it (the finer reference must change the answer).
awk -F, 'NR > 1 { if (!($8 > 0 && $8 < 0.5)) { bad = 1; print "FAILED: " $1 ":" $2 " relative RMS error " $8 } }
  END { exit bad }' "$out/brain.csv" || status=1
exit $status
