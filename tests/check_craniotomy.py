"""The craniotomy of a scenario, read with VTK from scenario.vtu.

usage: check_craniotomy.py SCENARIO_VTU CX CY CZ R MIN_OUT

The ball (centre, radius in mm, mesh geometry) is the opening. Checks
that no node inside it is in contact or carries contact pressure, and that
the pre-stressed model's nodes inside it move out through the opening
(their mean shift along the outward direction, from the body's centroid to
the opening's centre, above MIN_OUT mm): a skull still there would hold
them.
Exits 1 with the figures if not.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


def main():
    path = sys.argv[1]
    centre = np.array([float(v) for v in sys.argv[2:5]])
    radius = float(sys.argv[5])
    least_out = float(sys.argv[6])
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    data = grid.GetPointData()
    shift = vtk_to_numpy(data.GetArray("prestressed_shift_mm"))
    active = vtk_to_numpy(data.GetArray("contact_active"))
    pressure = vtk_to_numpy(data.GetArray("contact_pressure_Pa"))
    # The written points are the pre-stressed model's end state.
    start = points - shift
    inside = np.linalg.norm(start - centre, axis=1) <= radius
    outward = centre - start.mean(axis=0)
    outward /= np.linalg.norm(outward)
    failures = []
    if inside.sum() == 0:
        failures.append("no node lies in the opening")
    # Contact pressure: NaN off the contact candidates.
    pushed = np.nan_to_num(np.abs(pressure), nan=0.0)
    if np.any(active[inside] != 0) or np.any(pushed[inside] != 0):
        failures.append(
            "%d nodes in the opening are in contact (largest pressure %g Pa)"
            % (np.count_nonzero(active[inside]), pushed[inside].max())
        )
    out = float((shift[inside] @ outward).mean()) if inside.any() else 0.0
    if not out > least_out:
        failures.append(
            "the opening's nodes move %.3f mm outward (expected more than "
            "%g mm)" % (out, least_out)
        )
    if failures:
        print("FAIL: " + "; ".join(failures))
        return 1
    print(
        "ok: %d nodes in the opening, none in contact, moving out by %.3f mm "
        "on average (largest contact pressure outside it %.1f Pa)"
        % (inside.sum(), out, pushed[~inside].max())
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
