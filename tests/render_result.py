#!/usr/bin/python3
"""Renders a result as a user first sees it in ParaView: the outer surface
of a VTU (quadratic cells subdivided by VTK's own surface filter), coloured
by the magnitude of a point field, offscreen (run under xvfb-run), and
writes the picture as PNG. Fails unless the picture shows the body: at
least 5 % of the pixels differ from the white background, in at least 20
distinct colours (a field that varies, not a blank or a flat colour).

usage: render_result.py RESULT.vtu FIELD PICTURE.png
"""
import sys

import numpy
import vtk
from vtkmodules.util.numpy_support import vtk_to_numpy

MIN_COVERED = 0.05
MIN_COLOURS = 20


def main(path, field, picture):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    array = grid.GetPointData().GetArray(field)
    if grid.GetNumberOfCells() == 0 or array is None:
        print(f'FAIL: {path}: {grid.GetNumberOfCells()} cells, field {field}'
              f' {"missing" if array is None else "present"}')
        return 1
    magnitude = vtk.vtkArrayCalculator()
    magnitude.SetInputData(grid)
    magnitude.AddVectorArrayName(field)
    magnitude.SetFunction(f'mag({field})')
    magnitude.SetResultArrayName('magnitude')
    magnitude.Update()
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputConnection(magnitude.GetOutputPort())
    surface.SetNonlinearSubdivisionLevel(2)
    surface.Update()
    values = vtk_to_numpy(surface.GetOutput().GetPointData().GetArray('magnitude'))
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray('magnitude')
    mapper.SetScalarRange(float(values.min()), float(values.max()))
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1, 1, 1)
    renderer.ResetCamera()
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(400, 400)
    window.Render()
    capture = vtk.vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(picture)
    writer.SetInputConnection(capture.GetOutputPort())
    writer.Write()
    pixels = vtk_to_numpy(capture.GetOutput().GetPointData().GetScalars())
    covered = numpy.mean(numpy.any(pixels[:, :3] != 255, axis=1))
    colours = len(numpy.unique(pixels[:, :3], axis=0))
    print(f'{picture}: {100 * covered:.1f} % of the pixels show the body, '
          f'{colours} colours; {field} from {values.min():.3g} to '
          f'{values.max():.3g}')
    if covered < MIN_COVERED or colours < MIN_COLOURS:
        print('FAIL: the picture is blank or flat')
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main(*sys.argv[1:4]))
