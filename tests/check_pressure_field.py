#!/usr/bin/python3
"""The pressure field of a Lame shell run as ParaView reads it (VTK's XML
reader, the last solution-*.vtu of the run's directory): the cell field
pressure_Pa against the exact pressure -tr(sigma)/3 = -3 K A, constant in
the Lame shell (check_lame_shell.py gives A). A pressure checkerboard is a
field that oscillates from cell to cell about the right mean; so besides
the mean it measures, relative to the exact pressure:

- scatter: the RMS of the cells' pressure about the exact one;
- jump: the RMS of the pressure's jump across the faces two tetrahedra
  share (a checkerboard makes it as large as the scatter or larger).

Prints one line and fails (exit 1) if the mean is outside --mean (a range
of ratios), the scatter or the jump is above --scatter or --jump, or the
cells' volume_ratio differs from 1 by more than --volume-change.

usage: check_pressure_field.py RUN_DIRECTORY --E E --nu NU --p-inner P
       [--p-outer P] [--support K] [--radii A,B] [--mean LO,HI]
       [--scatter S] [--jump S] [--volume-change D] [--label TEXT]"""
import argparse
import glob
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_lame_shell import add_shell_arguments, shell_solution  # noqa: E402

TETRA_TYPES = (vtk.VTK_TETRA, vtk.VTK_QUADRATIC_TETRA, vtk.VTK_LAGRANGE_TETRAHEDRON)


def face_jumps(grid, pressure):
    """The pressure's jump across each face two tetrahedra share. DataOut
    writes each cell's points apart, so the vertices are matched by their
    position (to 1e-9 of the mesh's extent)."""
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    scale = max(np.ptp(points, axis=0).max(), 1e-300)
    keys = np.round(points / (1e-9 * scale)).astype(np.int64)
    _, vertex = np.unique(keys, axis=0, return_inverse=True)
    vertex = vertex.ravel()
    faces = {}
    for c in range(grid.GetNumberOfCells()):
        if grid.GetCellType(c) not in TETRA_TYPES:
            continue
        ids = grid.GetCell(c).GetPointIds()
        v = [int(vertex[ids.GetId(i)]) for i in range(4)]  # vertices first
        for skip in range(4):
            key = tuple(sorted(v[:skip] + v[skip + 1 :]))
            faces.setdefault(key, []).append(c)
    pairs = np.array([cs for cs in faces.values() if len(cs) == 2])
    if len(pairs) == 0:
        return np.zeros(0)
    return pressure[pairs[:, 0]] - pressure[pairs[:, 1]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run")
    add_shell_arguments(parser)
    parser.add_argument("--mean", default="0.9,1.1")
    parser.add_argument("--scatter", type=float, default=0.5)
    parser.add_argument("--jump", type=float, default=0.5)
    parser.add_argument("--volume-change", type=float, default=float("inf"))
    args = parser.parse_args()
    files = sorted(glob.glob(os.path.join(args.run, "solution-*.vtu")))
    if not files:
        print(f"{args.label}: no solution-*.vtu in {args.run}")
        return 1
    _, _, bulk, A, _ = shell_solution(args)
    exact = -3 * bulk * A
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(files[-1])
    reader.Update()
    grid = reader.GetOutput()
    array = grid.GetCellData().GetArray("pressure_Pa")
    if array is None:
        print(f"{args.label}: {files[-1]} has no cell field pressure_Pa")
        return 1
    p = vtk_to_numpy(array).astype(float)
    J = grid.GetCellData().GetArray("volume_ratio")
    change = float(np.abs(vtk_to_numpy(J) - 1).max()) if J is not None else float("nan")
    ratio = p.mean() / exact
    scatter = np.sqrt(np.mean((p - exact) ** 2)) / abs(exact)
    jumps = face_jumps(grid, p)
    jump = np.sqrt(np.mean(jumps**2)) / abs(exact) if len(jumps) else float("nan")
    lo, hi = (float(x) for x in args.mean.split(","))
    ok = (
        np.isfinite(p).all()
        and lo <= ratio <= hi
        and scatter <= args.scatter
        and len(jumps) > 0
        and jump <= args.jump
        and (args.volume_change == float("inf") or change <= args.volume_change)
    )
    print(
        f"{args.label}: pressure_Pa mean {p.mean():.4g} Pa, exact {exact:.4g} Pa, "
        f"ratio {ratio:.4f} (in [{lo}, {hi}]); scatter {scatter:.3f} (at most "
        f"{args.scatter}), jump across {len(jumps)} faces {jump:.3f} (at most "
        f"{args.jump}) of the exact pressure; volume_ratio within {change:.3g} of 1 "
        f"(at most {args.volume_change}): {'ok' if ok else 'FAIL'}"
    )
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
