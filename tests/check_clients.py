#!/usr/bin/python3
"""Reads what the scene tests wrote with the programs users read it with:
every .pvd, .vtu and .pvtu with VTK's own XML readers (python3-vtk9),
every rest_shape.msh with gmsh's reader (python3-gmsh) and with meshio
(python3-meshio), and checks them against the run's summary.json:

- VTU/PVTU: points and cells present; one VTK cell per mesh cell
  (n_cells), of the type the element gives (tetrahedron 10, quadratic
  tetrahedron 24, hexahedron 12, Lagrange hexahedron 72); the distinct
  points of the final state are the mesh's nodes (n_nodes); every array
  has one tuple per point (point data) or per cell (cell data); `label` is
  Int32 cell data, `von_mises_Pa`, `pressure_Pa` and `volume_ratio`
  Float64 cell data; the displacement
  field exists and is finite; contact runs carry the contact fields,
  inverse runs the error and shape fields, runs with an error estimate
  the `estimated_error` cell field.
- PVD: every DataSet it lists exists and reads, times increase.
- rest_shape.msh: gmsh and meshio read as many nodes as the mesh has
  (n_nodes of the vertices), as many cells as n_cells, the physical names
  of label_names.txt, and the node data "target_position" (3 components
  per node) and element data "image_mass_ratio".

usage: check_clients.py OUTPUT_DIRECTORY...   (each directory a run's
Output/Directory, or a directory of them: every subdirectory with a
summary.json is checked). Prints one line per file; exits 1 on the first
list of failures.
"""
import glob
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import vtk
from vtkmodules.util.numpy_support import vtk_to_numpy

from vtk_grid import read_grid

CELL_TYPES = {('tetrahedra', 1): vtk.VTK_TETRA,
              ('tetrahedra', 2): vtk.VTK_QUADRATIC_TETRA,
              ('hexahedra', 1): vtk.VTK_HEXAHEDRON,
              ('hexahedra', 2): vtk.VTK_LAGRANGE_HEXAHEDRON}

failures = []


def fail(path, text):
    failures.append(f'{path}: {text}')


def distinct_points(grid):
    """Points that coincide exactly (each patch repeats its cell's nodes,
    computed from the same values) count once."""
    import numpy
    points = vtk_to_numpy(grid.GetPoints().GetData())
    return len(numpy.unique(points, axis=0))


def array_names(data):
    return {data.GetArrayName(i) for i in range(data.GetNumberOfArrays())}


def expected_fields(summary, unit):
    """(point arrays, cell arrays) every state of this run must carry."""
    points = {'displacement_' + unit}
    cells = {'label', 'von_mises_Pa', 'pressure_Pa', 'volume_ratio'}
    if 'active_contact_nodes' in summary:
        points |= {'contact_active', 'contact_gap_' + unit,
                   'contact_pressure_Pa'}
    return points, cells


def check_grid(path, grid, summary, unit, final):
    """Counts, cell types, array lengths and types of one VTU/PVTU."""
    n_points, n_cells = grid.GetNumberOfPoints(), grid.GetNumberOfCells()
    if n_points == 0 or n_cells == 0:
        fail(path, f'{n_points} points and {n_cells} cells')
        return
    kind = (summary.get('cell_type'), summary.get('polynomial_degree'))
    types = {grid.GetCellType(i) for i in range(n_cells)}
    if kind in CELL_TYPES and types != {CELL_TYPES[kind]}:
        fail(path, f'cell types {sorted(types)}, expected '
                   f'{CELL_TYPES[kind]} for {kind}')
    if final:
        if n_cells != summary['n_cells']:
            fail(path, f'{n_cells} cells, the run reports {summary["n_cells"]}')
        nodes = distinct_points(grid)
        if nodes != summary['n_nodes']:
            fail(path, f'{nodes} distinct points, the run reports '
                       f'{summary["n_nodes"]} nodes')
    pd, cd = grid.GetPointData(), grid.GetCellData()
    for data, n, where in ((pd, n_points, 'point'), (cd, n_cells, 'cell')):
        for i in range(data.GetNumberOfArrays()):
            a = data.GetArray(i)
            if a.GetNumberOfTuples() != n:
                fail(path, f'{where} array {a.GetName()}: '
                           f'{a.GetNumberOfTuples()} tuples for {n} {where}s')
    points, cells = expected_fields(summary, unit)
    if 'estimated_error_relative' in summary and final:
        cells = cells | {'estimated_error'}
    for name in sorted(points - array_names(pd)):
        fail(path, f'no point array {name}')
    for name in sorted(cells - array_names(cd)):
        fail(path, f'no cell array {name}')
    label = cd.GetArray('label')
    if label is not None and label.GetDataTypeAsString() != 'int':
        fail(path, f'label is {label.GetDataTypeAsString()}, expected int')
    stress = cd.GetArray('von_mises_Pa')
    if stress is not None and stress.GetDataTypeAsString() != 'double':
        fail(path, f'von_mises_Pa is {stress.GetDataTypeAsString()}')
    displacement = pd.GetArray('displacement_' + unit)
    if displacement is not None:
        values = vtk_to_numpy(displacement)
        if values.ndim != 2 or values.shape[1] != 3 or \
                not all(math.isfinite(v) for v in values.ravel()):
            fail(path, 'displacement is not a finite 3-vector field')
    check_contact_fields(path, pd, summary, unit, final)


def check_contact_fields(path, pd, summary, unit, final):
    """Gap and pressure finite at every point (a NaN at one node once
    blanked every node of its cells: all of them at P2); in the final state
    with active nodes, some pressure and some node on the obstacle."""
    import numpy
    arrays = {}
    for name in ('contact_active', 'contact_gap_' + unit,
                 'contact_pressure_Pa'):
        a = pd.GetArray(name)
        if a is None:
            return
        arrays[name] = vtk_to_numpy(a)
        if not numpy.all(numpy.isfinite(arrays[name])):
            fail(path, f'{name}: {numpy.count_nonzero(~numpy.isfinite(arrays[name]))} '
                       f'of {len(arrays[name])} values are not finite')
            return
    if final and summary.get('active_contact_nodes', 0) > 0:
        active = arrays['contact_active'] == 1
        pressure = arrays['contact_pressure_Pa']
        gap = arrays['contact_gap_' + unit]
        if not active.any() or not numpy.any(pressure[active] > 0):
            fail(path, 'active contact nodes in summary.json, none with a '
                       'positive contact pressure in the file')
        elif numpy.abs(gap[active]).min() > 1e-3:
            fail(path, f'no active node touches the obstacle (smallest gap '
                       f'{numpy.abs(gap[active]).min()} {unit})')


def check_with_meshio(path, grid):
    """meshio reads the same points, cells and integer labels."""
    import meshio
    try:
        mesh = meshio.read(path)
    except Exception as e:  # meshio's own failure is the finding
        fail(path, f'meshio cannot read it: {type(e).__name__}: {e}')
        return
    n_cells = sum(len(block.data) for block in mesh.cells)
    if len(mesh.points) != grid.GetNumberOfPoints() or \
            n_cells != grid.GetNumberOfCells():
        fail(path, f'meshio reads {len(mesh.points)} points and {n_cells} '
                   f'cells, VTK {grid.GetNumberOfPoints()} and '
                   f'{grid.GetNumberOfCells()}')
    labels = mesh.cell_data.get('label')
    if labels is None or labels[0].dtype.kind != 'i':
        fail(path, 'meshio finds no integer cell data "label"')


def check_pvd(path):
    """Every listed file exists and reads; times increase."""
    root = ET.parse(path).getroot()
    times, files = [], []
    for dataset in root.iter('DataSet'):
        times.append(float(dataset.get('timestep')))
        files.append(os.path.join(os.path.dirname(path), dataset.get('file')))
    if not files:
        fail(path, 'lists no data set')
    if times != sorted(times):
        fail(path, f'times not increasing: {times}')
    for f in files:
        if not os.path.exists(f):
            fail(path, f'lists {f}, which does not exist')
        elif read_grid(f) is None:
            fail(path, f'lists {f}, which VTK cannot read')
    return files


def label_names(run):
    names = {}
    path = os.path.join(run, 'label_names.txt')
    if os.path.exists(path):
        for line in open(path):
            parts = line.split(None, 1)
            if len(parts) == 2 and not line.startswith('#'):
                names[int(parts[0])] = parts[1].strip()
    return names


def check_rest_shape(path, summary, names):
    """gmsh's and meshio's readers on a rest_shape.msh."""
    import gmsh
    import meshio
    # The file holds the mesh's vertices (the nodes of P1 and Q1).
    vertices = summary['n_nodes'] if summary.get(
        'polynomial_degree') == 1 else None
    gmsh.initialize(['', '-v', '0'])
    try:
        gmsh.open(path)
        tags, _, _ = gmsh.model.mesh.getNodes()
        types, elements, _ = gmsh.model.mesh.getElements(3)
        n_elements = sum(len(e) for e in elements)
        groups = {gmsh.model.getPhysicalName(3, tag)
                  for _, tag in gmsh.model.getPhysicalGroups(3)}
        views = {gmsh.option.getString(f'View[{gmsh.view.getIndex(v)}].Name')
                 for v in gmsh.view.getTags()}
    finally:
        gmsh.finalize()
    if n_elements != summary['n_cells']:
        fail(path, f'gmsh reads {n_elements} cells, the run reports '
                   f'{summary["n_cells"]}')
    if vertices is not None and len(tags) != vertices:
        fail(path, f'gmsh reads {len(tags)} nodes, the run reports {vertices}')
    for wanted in ('target_position', 'image_mass_ratio'):
        if wanted not in views:
            fail(path, f'gmsh finds no view {wanted} (views: {sorted(views)})')
    for name in names.values():
        if name not in groups:
            fail(path, f'gmsh finds no physical group "{name}"')
    mesh = meshio.read(path)
    n_meshio = sum(len(block.data) for block in mesh.cells)
    if n_meshio != n_elements:
        fail(path, f'meshio reads {n_meshio} cells, gmsh {n_elements}')
    if len(mesh.points) != len(tags):
        fail(path, f'meshio reads {len(mesh.points)} nodes, gmsh {len(tags)}')
    target = mesh.point_data.get('target_position')
    if target is None or target.shape != (len(mesh.points), 3):
        fail(path, 'meshio finds no 3-component target_position per node')
    return len(tags), n_elements


def check_run(run):
    summary = json.load(open(os.path.join(run, 'summary.json')))
    if not summary.get('converged', False):
        return
    unit = 'mm'
    prm = os.path.join(run, 'parameters.prm')
    if os.path.exists(prm) and any(
            line.split() == ['set', 'Length', 'unit', '=', 'm']
            for line in open(prm) if 'Length unit' in line):
        unit = 'm'
    final = set()
    for pvd in sorted(glob.glob(os.path.join(run, '*.pvd'))):
        files = check_pvd(pvd)
        if files:
            final.add(os.path.abspath(files[-1]))
        print(f'ok   pvd {pvd}: {len(files)} data sets')
    state = [f for f in glob.glob(os.path.join(run, 'prestressed_state.*'))
             if f.endswith(('.vtu', '.pvtu'))]
    final |= {os.path.abspath(f) for f in state}
    records = glob.glob(os.path.join(run, '*.pvtu'))
    pieces = {os.path.abspath(p) for r in records
              for p in glob.glob(r[:-5] + '.[0-9]*.vtu')}
    for path in sorted(glob.glob(os.path.join(run, '*.vtu')) + records):
        if os.path.abspath(path) in pieces:
            continue  # read through its .pvtu record
        grid = read_grid(path)
        if grid is None:
            fail(path, 'VTK cannot read it')
            continue
        check_grid(path, grid, summary, unit, os.path.abspath(path) in final)
        if path.endswith('.vtu'):
            check_with_meshio(path, grid)
        print(f'ok   {path}: {grid.GetNumberOfPoints()} points, '
              f'{grid.GetNumberOfCells()} cells')
    msh = os.path.join(run, 'rest_shape.msh')
    if os.path.exists(msh):
        nodes, cells = check_rest_shape(msh, summary, label_names(run))
        print(f'ok   {msh}: gmsh and meshio read {nodes} nodes, {cells} cells')


def main():
    runs = []
    for top in sys.argv[1:]:
        for summary in glob.glob(os.path.join(top, '**', 'summary.json'),
                                 recursive=True):
            runs.append(os.path.dirname(summary))
    if not runs:
        print('no run found under', sys.argv[1:])
        return 1
    for run in sorted(runs):
        check_run(run)
    for f in failures:
        print('FAIL', f)
    print(f'{len(runs)} runs read, {len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
