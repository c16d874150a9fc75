#!/usr/bin/python3
"""The contact pressure field of a VTU as a user reads it (VTK's XML
reader, ParaView's): over the active nodes (contact_active = 1), its
largest value over its mean, and each node's value over the mean of its
active neighbours (nodes sharing a cell with it): a single-node spike
shows as a large ratio. With --hertz F E NU R (N, Pa, -, m), the field's
peak against Hertz's p0 = 3 F / (2 pi a^2), a = (3 F R / (4 E*))^(1/3).

usage: check_contact_pressure.py FILE.vtu [--max-neighbour-ratio X]
           [--max-peak-over-mean X] [--hertz F E NU R --peak-tolerance T]
Exits 1 if a limit is exceeded."""
import argparse
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    if data.GetArray("contact_pressure_Pa") is None:
        sys.exit(f"{path}: no contact_pressure_Pa field")
    points = vtk_to_numpy(grid.GetPoints().GetData())
    # deal.II writes each cell's points apart: merge equal positions.
    _, node = np.unique(np.round(points, 9), axis=0, return_inverse=True)
    n = node.max() + 1
    pressure, active, position = np.zeros(n), np.zeros(n), np.zeros((n, 3))
    pressure[node] = vtk_to_numpy(data.GetArray("contact_pressure_Pa"))
    active[node] = vtk_to_numpy(data.GetArray("contact_active"))
    position[node] = points
    neighbours = [set() for _ in range(n)]
    ids = vtk.vtkIdList()
    for c in range(grid.GetNumberOfCells()):
        grid.GetCellPoints(c, ids)
        cell = {node[ids.GetId(k)] for k in range(ids.GetNumberOfIds())}
        for i in cell:
            neighbours[i] |= cell
    return pressure, active > 0.5, position, neighbours


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("vtu")
    parser.add_argument("--max-neighbour-ratio", type=float)
    parser.add_argument("--max-peak-over-mean", type=float)
    parser.add_argument("--hertz", type=float, nargs=4)
    parser.add_argument("--peak-tolerance", type=float, default=0.1)
    args = parser.parse_args()
    pressure, active, position, neighbours = read(args.vtu)
    on = np.where(active)[0]
    if len(on) == 0:
        sys.exit(f"{args.vtu}: no active contact node")
    peak, mean = pressure[on].max(), pressure[on].mean()
    ratios = []
    for i in on:
        others = [j for j in neighbours[i] if j != i and active[j]]
        if others and pressure[others].mean() > 0:
            ratios.append(pressure[i] / pressure[others].mean())
    worst = max(ratios) if ratios else 0.0
    print(f"{args.vtu}: {len(on)} active nodes, pressure mean {mean:.4g} Pa, "
          f"peak {peak:.4g} Pa ({peak / mean:.2f} times the mean), largest "
          f"ratio of a node to its active neighbours' mean {worst:.2f}")
    failed = False
    if args.max_neighbour_ratio is not None and worst > args.max_neighbour_ratio:
        print(f"FAIL: a node {worst:.2f} times its neighbours' mean "
              f"(limit {args.max_neighbour_ratio})")
        failed = True
    if args.max_peak_over_mean is not None and peak / mean > args.max_peak_over_mean:
        print(f"FAIL: peak {peak / mean:.2f} times the mean "
              f"(limit {args.max_peak_over_mean})")
        failed = True
    if args.hertz:
        force, young, nu, radius = args.hertz
        a = (3 * force * radius / (4 * young / (1 - nu**2))) ** (1 / 3)
        p0 = 3 * force / (2 * np.pi * a**2)
        error = peak / p0 - 1
        print(f"Hertz: contact radius {a * 1e3:.4g} mm, p0 {p0:.4g} Pa; "
              f"the field's peak {100 * error:+.1f} %")
        if abs(error) > args.peak_tolerance:
            print(f"FAIL: peak off Hertz's by more than "
                  f"{100 * args.peak_tolerance:g} %")
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
