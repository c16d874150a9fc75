#!/usr/bin/env python3
# Figures of doc/brain.md from the outputs of prm/brain.prm and
# prm/brain_paper_method.prm (run both first). Debian packages:
# python3-vtk9, python3-matplotlib, xvfb. Run from the repository root:
#
#   xvfb-run -a python3 doc/make_figures.py
#
# Writes doc/figures/brain_shapes.png (target, rest and equilibrium surfaces,
# lateral view from the left), doc/figures/brain_error.png (the error
# |X_target - X_equilibrium| on the equilibrium surface, from the left and
# from below) and doc/figures/brain_iterations.png (mean and max error per
# inverse iteration for both methods).
import csv
import glob
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
import vtk
from vtk.util.numpy_support import vtk_to_numpy, numpy_to_vtk


def last_vtu(directory):
    files = sorted(glob.glob(os.path.join(directory, 'solution-*.vtu')))
    if not files:
        raise SystemExit('no solution-*.vtu in ' + directory + ': run the scene first')
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(files[-1])
    reader.Update()
    return reader.GetOutput()


def surface_at(grid, positions):
    copy = vtk.vtkUnstructuredGrid()
    copy.DeepCopy(grid)
    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(vtk_to_numpy(grid.GetPointData().GetArray(positions)).copy(), deep=1))
    copy.SetPoints(points)
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputData(copy)
    surface.Update()
    return surface.GetOutput()


def render(actors, file, view_up=(0, 0, 1), direction=(1, 0, 0), bar=None, size=(900, 700)):
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    for a in actors:
        renderer.AddActor(a)
    if bar is not None:
        renderer.AddActor2D(bar)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(*[-500 * d for d in direction])
    camera.SetViewUp(*view_up)
    renderer.ResetCamera()
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(file)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def actor(poly, color=None, opacity=1.0, scalars=None, lut=None, wire=False):
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
    if color:
        a.GetProperty().SetColor(*color)
    a.GetProperty().SetOpacity(opacity)
    if wire:
        a.GetProperty().SetRepresentationToWireframe()
    return a


def shapes_and_error(directory, tag):
    grid = last_vtu(directory)
    target = surface_at(grid, 'target_position_mm')
    rest = surface_at(grid, 'rest_position_mm')
    equilibrium = surface_at(grid, 'equilibrium_position_mm')
    # Lateral view from the left (camera at -x looking to +x), superior up.
    render([actor(rest, (0.2, 0.35, 0.9), 0.35), actor(target, (0.85, 0.15, 0.1), wire=True),
            actor(equilibrium, (0.6, 0.6, 0.6), 0.5)],
           'doc/figures/brain_shapes%s.png' % tag, direction=(1, 0, 0))
    errors = vtk_to_numpy(grid.GetPointData().GetArray('error_magnitude_mm'))
    lut = vtk.vtkLookupTable()
    lut.SetRange(0, float(errors.max()))
    lut.SetHueRange(0.15, 0.67)
    lut.Build()
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle('error (mm)')
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    bar.SetNumberOfLabels(5)
    render([actor(equilibrium, scalars='error_magnitude_mm', lut=lut)],
           'doc/figures/brain_error%s_left.png' % tag, direction=(1, 0, 0), bar=bar)
    render([actor(equilibrium, scalars='error_magnitude_mm', lut=lut)],
           'doc/figures/brain_error%s_below.png' % tag, direction=(0, 0, 1), view_up=(0, 1, 0), bar=bar)


def read_iterations(directory):
    with open(os.path.join(directory, 'iterations.csv')) as f:
        rows = list(csv.DictReader(f))
    return ([int(r['iteration']) for r in rows], [float(r['mean_error_mm']) for r in rows],
            [float(r['max_error_mm']) for r in rows])


os.makedirs('doc/figures', exist_ok=True)
shapes_and_error('output/brain', '')
plt.figure(figsize=(6.5, 4))
for directory, label, style in (('output/brain', 'RestShape (Anderson, consistent, P1)', '-o'),
                                ('output/brain_paper_method', "paper's method (plain, warped, P1)", '--s')):
    if os.path.exists(os.path.join(directory, 'iterations.csv')):
        it, mean, maximum = read_iterations(directory)
        plt.semilogy(it, mean, style, label=label + ': mean')
        plt.semilogy(it, maximum, style, alpha=0.5, label=label + ': max')
plt.axhline(0.746, color='gray', lw=0.8, ls=':')
plt.text(0, 0.8, 'paper: mean 0.746 mm after 6 iterations', fontsize=8, color='gray')
plt.xlabel('inverse iteration')
plt.ylabel('|X_target - X_equilibrium| (mm)')
plt.legend(fontsize=7)
plt.grid(True, which='both', alpha=0.3)
plt.tight_layout()
plt.savefig('doc/figures/brain_iterations.png', dpi=120)
print('wrote doc/figures/brain_shapes.png, brain_error_left.png, brain_error_below.png, brain_iterations.png')
