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
of ratios) or the scatter or the jump is above --scatter or --jump.

usage: check_pressure_field.py RUN_DIRECTORY --E E --nu NU --p-inner P
       [--p-outer P] [--support K] [--radii A,B] [--mean LO,HI]
       [--scatter S] [--jump S] [--label TEXT]"""
import argparse
import glob
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_lame_shell import closed_form  # noqa: E402

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
    parser.add_argument("--E", type=float, required=True)
    parser.add_argument("--nu", type=float, required=True)
    parser.add_argument("--p-inner", type=float, required=True)
    parser.add_argument("--p-outer", type=float, default=0)
    parser.add_argument("--support", type=float, default=0)
    parser.add_argument("--radii", default="10,20")
    parser.add_argument("--mean", default="0.9,1.1")
    parser.add_argument("--scatter", type=float, default=0.5)
    parser.add_argument("--jump", type=float, default=0.5)
    parser.add_argument("--label", default="shell")
    args = parser.parse_args()
    files = sorted(glob.glob(os.path.join(args.run, "solution-*.vtu")))
    if not files:
        print(f"{args.label}: no solution-*.vtu in {args.run}")
        return 1
    a, b = (float(x) * 1e-3 for x in args.radii.split(","))
    mu = args.E / (2 * (1 + args.nu))
    bulk = args.E / (3 * (1 - 2 * args.nu))
    A, _ = closed_form(mu, bulk, a, b, args.p_inner, args.p_outer, args.support)
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
    )
    print(
        f"{args.label}: pressure_Pa mean {p.mean():.4g} Pa, exact {exact:.4g} Pa, "
        f"ratio {ratio:.4f} (in [{lo}, {hi}]); scatter {scatter:.3f} (at most "
        f"{args.scatter}), jump across {len(jumps)} faces {jump:.3f} (at most "
        f"{args.jump}) of the exact pressure: {'ok' if ok else 'FAIL'}"
    )
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
