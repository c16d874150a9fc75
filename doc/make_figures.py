#!/usr/bin/env python3
# Figures of doc/brain.md from the outputs of prm/brain.prm and
# prm/brain_paper_method.prm (run both first). Debian packages:
# python3-vtk9, python3-matplotlib (the iteration plot only), xvfb. Run from the repository root:
#
#   xvfb-run -a python3 doc/make_figures.py
#
# With the argument `in_vivo`, only doc/figures/brain_in_vivo.png, from
# prm/brain_in_vivo.prm (doc/brain.md, section 8):
#
#   build/restshape prm/brain_in_vivo.prm
#   xvfb-run -a python3 doc/make_figures.py in_vivo
#
# With the argument `scenarios`, only doc/figures/brain_scenarios.png, from
# two scenarios of prm/brain.prm (doc/scenarios.md):
#
#   build/restshape prm/brain_shift_prone.prm
#   build/restshape prm/brain_shift_drained.prm
#   build/restshape prm/brain_shift_craniotomy.prm
#   xvfb-run -a python3 doc/make_figures.py scenarios
#
# (and doc/figures/brain_craniotomy.png from the last). With the argument
# `csf`, only doc/figures/brain_csf.png, from prm/brain_shift_csf.prm:
#
#   build/restshape prm/brain_shift_csf.prm
#   xvfb-run -a python3 doc/make_figures.py csf
#
# Writes doc/figures/brain_shapes.png (target, rest and equilibrium surfaces,
# lateral view from the left), doc/figures/brain_error.png (the error
# |X_target - X_equilibrium| on the equilibrium surface, from the left and
# from below) and doc/figures/brain_iterations.png (mean and max error per
# inverse iteration for both methods). With the argument `tracts`, only
# doc/figures/brain_tracts.png, from the outputs of prm/brain_tracts.prm
# and of the same scene with uniform stiffness:
#
#   build/restshape prm/brain_tracts.prm
#   build/restshape prm/brain_tracts.prm \
#     --set "Materials/Young's modulus=tumour:10000, *:1500" \
#     --set Output/Directory=output/brain_tracts_uniform
#   xvfb-run -a python3 doc/make_figures.py tracts
import csv
import sys
import glob
import os

import numpy
import vtk
from vtk.util.numpy_support import vtk_to_numpy, numpy_to_vtk


def read_vtu(file):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(file)
    reader.Update()
    return reader.GetOutput()


def vtus(directory):
    files = sorted(glob.glob(os.path.join(directory, 'solution-*.vtu')))
    if not files:
        raise SystemExit('no solution-*.vtu in ' + directory + ': run the scene first')
    return files


def surface_at(grid, positions, scalars=None, values=None):
    """The outer surface of grid, its points moved to the point field
    `positions` (mm; None: where they are), with the point field `values`
    as `scalars`."""
    copy = vtk.vtkUnstructuredGrid()
    copy.DeepCopy(grid)
    if positions is not None:
        points = vtk.vtkPoints()
        points.SetData(numpy_to_vtk(vtk_to_numpy(grid.GetPointData().GetArray(positions)).copy(), deep=1))
        copy.SetPoints(points)
    if scalars is not None:
        array = numpy_to_vtk(values.copy(), deep=1)
        array.SetName(scalars)
        copy.GetPointData().AddArray(array)
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputData(copy)
    surface.Update()
    return surface.GetOutput()


def magnitude(grid, a, b=None):
    """|a - b| of two point fields (|a| if b is None)."""
    va = vtk_to_numpy(grid.GetPointData().GetArray(a))
    vb = 0 if b is None else vtk_to_numpy(grid.GetPointData().GetArray(b))
    return numpy.linalg.norm(va - vb, axis=1)


def colour_map(maximum, title):
    """maximum: the top of the range from 0, or a (bottom, top) pair."""
    lut = vtk.vtkLookupTable()
    lut.SetRange(*(maximum if isinstance(maximum, tuple) else (0, maximum)))
    lut.SetHueRange(0.15, 0.67)
    lut.Build()
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(title)
    bar.SetMaximumWidthInPixels(70)
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    bar.SetNumberOfLabels(4)
    return lut, bar


def actor(poly, scalars=None, lut=None):
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(poly)
    if scalars:
        poly.GetPointData().SetActiveScalars(scalars)
        mapper.SetScalarModeToUsePointData()
        mapper.SetLookupTable(lut)
        mapper.SetScalarRange(lut.GetRange())
        mapper.ScalarVisibilityOn()
    else:
        mapper.ScalarVisibilityOff()
    a = vtk.vtkActor()
    a.SetMapper(mapper)
    if not scalars:
        a.GetProperty().SetColor(0.8, 0.8, 0.8)
    return a


def render_panels(panels, file, direction=(1, 0, 0), view_up=(0, 0, 1), size=(1500, 520)):
    """panels: (title, polydata, scalars or None, maximum[, bar title, default
    mm]); one viewport each,
    lateral view from the left (camera at -x), superior up."""
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    for i, (title, poly, scalars, maximum, *unit) in enumerate(panels):
        renderer = vtk.vtkRenderer()
        renderer.SetViewport(i / len(panels), 0, (i + 1) / len(panels), 1)
        renderer.SetBackground(1, 1, 1)
        lut, bar = colour_map(maximum, (unit or ['mm'])[0]) if scalars else (None, None)
        renderer.AddActor(actor(poly, scalars, lut))
        if bar is not None:
            renderer.AddActor2D(bar)
        text = vtk.vtkTextActor()
        text.SetInput(title)
        text.GetTextProperty().SetColor(0, 0, 0)
        text.GetTextProperty().SetFontSize(16)
        text.SetPosition(10, size[1] - 30)
        renderer.AddActor2D(text)
        camera = renderer.GetActiveCamera()
        camera.SetFocalPoint(0, 0, 0)
        camera.SetPosition(*[-500 * d for d in direction])
        camera.SetViewUp(*view_up)
        renderer.ResetCamera()
        camera.Zoom(1.3)
        window.AddRenderer(renderer)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(file)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def shapes(directory):
    grid = read_vtu(vtus(directory)[-1])
    correction = magnitude(grid, 'rest_position_mm', 'target_position_mm')
    sag = magnitude(grid, 'equilibrium_position_mm', 'rest_position_mm')
    render_panels([('target (image)', surface_at(grid, 'target_position_mm'), None, 0),
                   ('rest shape: |X_rest - X_target|',
                    surface_at(grid, 'rest_position_mm', 'c', correction), 'c', correction.max()),
                   ('equilibrium: |x - X_rest|',
                    surface_at(grid, 'equilibrium_position_mm', 's', sag), 's', sag.max())],
                  'doc/figures/brain_shapes.png')


def errors(ours, paper):
    first = read_vtu(vtus(ours)[0])
    last_paper = read_vtu(vtus(paper)[-1])
    last = read_vtu(vtus(ours)[-1])
    panels = []
    for title, grid in (('iteration 0 (no rest shape)', first),
                        ("paper's method, last iterate", last_paper),
                        ('RestShape, converged', last)):
        e = magnitude(grid, 'error_mm')
        panels.append(('%s: max %.3g mm' % (title, e.max()),
                       surface_at(grid, 'equilibrium_position_mm', 'e', e), 'e', e.max()))
    render_panels(panels, 'doc/figures/brain_error_left.png')
    render_panels(panels, 'doc/figures/brain_error_below.png', direction=(0, 0, 1), view_up=(0, 1, 0))


def read_iterations(directory):
    with open(os.path.join(directory, 'iterations.csv')) as f:
        rows = list(csv.DictReader(f))
    return ([int(r['iteration']) for r in rows], [float(r['mean_error_mm']) for r in rows],
            [float(r['max_error_mm']) for r in rows])


def cut(grid, positions, y, name, values):
    """The section y = const (mm) of grid, its points at the point field
    `positions`, with the point field `values` as `name`."""
    copy = vtk.vtkUnstructuredGrid()
    copy.DeepCopy(grid)
    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(vtk_to_numpy(grid.GetPointData().GetArray(positions)).copy(), deep=1))
    copy.SetPoints(points)
    array = numpy_to_vtk(numpy.asarray(values, dtype=float).copy(), deep=1)
    array.SetName(name)
    copy.GetPointData().AddArray(array)
    plane = vtk.vtkPlane()
    plane.SetOrigin(0, y, 0)
    plane.SetNormal(0, 1, 0)
    cutter = vtk.vtkCutter()
    cutter.SetCutFunction(plane)
    cutter.SetInputData(copy)
    cutter.Update()
    return cutter.GetOutput()


def tracts(heterogeneous, uniform):
    """Labels on a coronal section, the rest-shape correction, and where the
    softer tracts move the rest shape (both runs on the same mesh)."""
    a = read_vtu(vtus(heterogeneous)[-1])
    b = read_vtu(vtus(uniform)[-1])
    rest_a = vtk_to_numpy(a.GetPointData().GetArray('rest_position_mm'))
    rest_b = vtk_to_numpy(b.GetPointData().GetArray('rest_position_mm'))
    shift = numpy.linalg.norm(rest_a - rest_b, axis=1)
    correction = magnitude(a, 'rest_position_mm', 'target_position_mm')
    # label is cell data; each cell has points of its own (deal.II writes
    # a patch per cell), so the point value is the cell's.
    to_points = vtk.vtkCellDataToPointData()
    to_points.SetInputData(a)
    to_points.Update()
    label = vtk_to_numpy(to_points.GetOutput().GetPointData().GetArray('label'))
    section = 2.0  # mm: through the body of the corpus callosum
    front = dict(direction=(0, -1, 0), view_up=(0, 0, 1))
    render_panels([('labels, coronal section y = %g mm (tracts: 5)' % section,
                    cut(a, 'target_position_mm', section, 'l', label), 'l', label.max(), 'label'),
                   ('rest shape: |X_rest - X_target|, max %.2f mm' % correction.max(),
                    surface_at(a, 'rest_position_mm', 'c', correction), 'c', correction.max()),
                   ('softer tracts move it by up to %.2f mm' % shift.max(),
                    cut(a, 'target_position_mm', section, 's', shift), 's', shift.max())],
                  'doc/figures/brain_tracts.png', **front)
    unique = numpy.unique(vtk_to_numpy(a.GetPointData().GetArray('target_position_mm')),
                          axis=0, return_index=True)[1]
    print('rest shapes, tracts at half stiffness vs uniform: mean %.4f, max %.4f mm'
          % (shift[unique].mean(), shift.max()))
    print('rest-shape correction: mean %.4f / %.4f mm, max %.4f / %.4f mm' % (
        correction[unique].mean(),
        magnitude(b, 'rest_position_mm', 'target_position_mm')[unique].mean(),
        correction.max(), magnitude(b, 'rest_position_mm', 'target_position_mm').max()))
    print('wrote doc/figures/brain_tracts.png')


def scenarios(prone, drained):
    """The pre-stressed brain's shift in two scenarios, and where the
    stress-free model differs in the second, on the deformed surface."""
    a = read_vtu(os.path.join(prone, 'scenario.vtu'))
    b = read_vtu(os.path.join(drained, 'scenario.vtu'))
    shift_a = magnitude(a, 'prestressed_shift_mm')
    shift_b = magnitude(b, 'prestressed_shift_mm')
    diff_b = magnitude(b, 'stress_free_shift_mm', 'prestressed_shift_mm')
    render_panels([('supine to prone: shift, max %.2f mm' % shift_a.max(),
                    surface_at(a, None, 's', shift_a), 's', shift_a.max()),
                   ('drained above y = 20 mm: shift, max %.2f mm' % shift_b.max(),
                    surface_at(b, None, 't', shift_b), 't', shift_b.max()),
                   ('drained: |stress-free - pre-stressed|, max %.2f mm' % diff_b.max(),
                    surface_at(b, None, 'd', diff_b), 'd', diff_b.max())],
                  'doc/figures/brain_scenarios.png')
    print('wrote doc/figures/brain_scenarios.png')


def craniotomy(directory):
    """The frontal craniotomy: the pre-stressed brain's shift and where the
    stress-free model differs, seen from the front."""
    g = read_vtu(os.path.join(directory, 'scenario.vtu'))
    shift = magnitude(g, 'prestressed_shift_mm')
    diff = magnitude(g, 'stress_free_shift_mm', 'prestressed_shift_mm')
    render_panels([('craniotomy: shift, max %.2f mm' % shift.max(),
                    surface_at(g, None, 's', shift), 's', shift.max()),
                   ('|stress-free - pre-stressed|, max %.2f mm' % diff.max(),
                    surface_at(g, None, 'd', diff), 'd', diff.max())],
                  'doc/figures/brain_craniotomy.png', direction=(0, -1, 0),
                  size=(1000, 520))
    print('wrote doc/figures/brain_craniotomy.png')


def csf(directory):
    """The neo-Hookean brain in a hydrostatic CSF turned prone: the shift of
    both models, and the drained scenario's pre-stressed shift."""
    prone = read_vtu(os.path.join(directory, 'scenario_prone.vtu'))
    drained = read_vtu(os.path.join(directory, 'scenario_drained.vtu'))
    a = magnitude(prone, 'prestressed_shift_mm')
    b = magnitude(prone, 'stress_free_shift_mm')
    c = magnitude(drained, 'prestressed_shift_mm')
    top = max(a.max(), b.max())
    render_panels([('prone, pre-stressed: shift, max %.2f mm' % a.max(),
                    surface_at(prone, None, 'a', a), 'a', top),
                   ('prone, stress-free: shift, max %.2f mm' % b.max(),
                    surface_at(prone, None, 'b', b), 'b', top),
                   ('drained above y = 20 mm, pre-stressed: max %.2f mm' % c.max(),
                    surface_at(drained, None, 'c', c), 'c', c.max())],
                  'doc/figures/brain_csf.png')
    print('wrote doc/figures/brain_csf.png')


def in_vivo(directory):
    """prm/brain_in_vivo.prm: the cells' pressure and volume change on an
    axial section through the tumour (y = 29 mm, seen from above), and
    the pre-stressed shift of Table 1's scenario."""
    grid = read_vtu(vtus(directory)[0])
    # Cell fields; each cell has points of its own (deal.II writes a patch
    # per cell), so the point value is the cell's.
    to_points = vtk.vtkCellDataToPointData()
    to_points.SetInputData(grid)
    to_points.Update()
    fields = to_points.GetOutput().GetPointData()
    pressure = vtk_to_numpy(fields.GetArray('pressure_Pa'))
    change = 100 * (vtk_to_numpy(fields.GetArray('volume_ratio')) - 1)
    scenario = read_vtu(os.path.join(directory, 'scenario.vtu'))
    shift = magnitude(scenario, 'prestressed_shift_mm')
    section = 29.0  # mm: through the tumour's centroid
    above = dict(direction=(0, -1, 0), view_up=(0, 0, 1))
    cut_p = cut(grid, 'target_position_mm', section, 'p', pressure)
    cut_j = cut(grid, 'target_position_mm', section, 'j', change)
    p = vtk_to_numpy(cut_p.GetPointData().GetArray('p'))
    j = vtk_to_numpy(cut_j.GetPointData().GetArray('j'))
    top = float(numpy.abs(j).max())
    render_panels([('pressure, section y = %g mm: %.0f to %.0f Pa' % (section, p.min(), p.max()),
                    cut_p, 'p', (float(p.min()), float(p.max())), 'Pa'),
                   ('volume change J - 1 there: %.2f to %.2f %%' % (j.min(), j.max()),
                    cut_j, 'j', (-top, top), '%'),
                   ('Table 1 (0.1 g sideways): shift, max %.2f mm' % shift.max(),
                    surface_at(scenario, None, 's', shift), 's', shift.max())],
                  'doc/figures/brain_in_vivo.png', **above)
    print('wrote doc/figures/brain_in_vivo.png')


os.makedirs('doc/figures', exist_ok=True)
if sys.argv[1:] == ['in_vivo']:
    in_vivo('output/brain_in_vivo')
    raise SystemExit(0)
if sys.argv[1:] == ['csf']:
    csf('output/brain_shift_csf')
    raise SystemExit(0)
if sys.argv[1:] == ['scenarios']:
    scenarios('output/brain_shift_prone', 'output/brain_shift_drained')
    craniotomy('output/brain_shift_craniotomy')
    raise SystemExit(0)
if sys.argv[1:] == ['tracts']:
    tracts('output/brain_tracts', 'output/brain_tracts_uniform')
    raise SystemExit(0)
shapes('output/brain')
errors('output/brain', 'output/brain_paper_method')
import matplotlib  # noqa: E402 (only the iteration plot needs it)
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402
plt.figure(figsize=(6.5, 4))
for directory, label, style in (('output/brain', 'RestShape (Anderson, consistent, P1)', '-o'),
                                ('output/brain_paper_method', "paper's method (plain, warped, P1)", '--s')):
    if os.path.exists(os.path.join(directory, 'iterations.csv')):
        it, mean, maximum = read_iterations(directory)
        plt.semilogy(it, mean, style, label=label + ': mean')
        plt.semilogy(it, maximum, style, alpha=0.5, label=label + ': max')
plt.axhline(0.746, color='gray', lw=0.8, ls=':')
plt.text(3, 0.8, 'paper: mean 0.746 mm after 6 iterations', fontsize=8, color='gray')
plt.xlabel('inverse iteration')
plt.ylabel('|X_target - X_equilibrium| (mm)')
plt.legend(fontsize=7)
plt.grid(True, which='both', alpha=0.3)
plt.tight_layout()
plt.savefig('doc/figures/brain_iterations.png', dpi=120)
print('wrote doc/figures/brain_shapes.png, brain_error_left.png, brain_error_below.png, brain_iterations.png')
