#!/usr/bin/python3
"""Step-44's indented block against step-44 itself (deal.II's tutorial, the
peer), both read with VTK's XML reader: the displacement at every vertex of
the peer's final solution-3d-*.vtu (both write the deformed points)
against restshape's solution-*.vtu at the same rest position, the top
centre's vertical displacement, and the block's volume change

    v / V0 - 1 = sum over the cells of the deformed volume / rest volume - 1,

the deformed volume of each trilinear hexahedron integrated exactly (2x2x2
Gauss points) from restshape's displacement field, and again from its
volume_ratio cell field (J); the peer's from its dilatation field (cells of
equal rest volume). Fails (exit 1) when the largest nodal difference is
above --tolerance (mm) or a volume change above --volume (relative).

usage: check_indented_block.py PEER.vtu OURS.vtu [--tolerance MM]
       [--volume REL] [--length MM]"""
import argparse
import itertools
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

from vtk_grid import read_grid

# Vertex (xi, eta, zeta) of VTK's hexahedron, in its node order.
HEX_CORNERS = np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                        (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)], float)
GAUSS = (0.5 - 0.5 / np.sqrt(3), 0.5 + 0.5 / np.sqrt(3))


def read(path):
    grid = read_grid(path)
    if grid is None or grid.GetNumberOfPoints() == 0:
        sys.exit(f"check_indented_block.py: {path}: no points read")
    return grid


def array(data, name, path):
    a = data.GetArray(name)
    if a is None:
        sys.exit(f"check_indented_block.py: {path}: no array {name}")
    return vtk_to_numpy(a)


def hex_volume(x):
    """The volume of the trilinear hexahedron of vertices x (8 x 3)."""
    volume = 0.0
    for xi in itertools.product(GAUSS, repeat=3):
        grad = np.empty((8, 3))
        for a, c in enumerate(HEX_CORNERS):
            f = [c[d] * xi[d] + (1 - c[d]) * (1 - xi[d]) for d in range(3)]
            s = [2 * c[d] - 1 for d in range(3)]
            grad[a] = (s[0] * f[1] * f[2], f[0] * s[1] * f[2],
                       f[0] * f[1] * s[2])
        volume += np.linalg.det(x.T @ grad) / 8
    return volume


def corner_ids(grid):
    """Each cell's 8 corners (the first 8 points of a linear or a Lagrange
    hexahedron), by cell."""
    return [[grid.GetCell(c).GetPointId(i) for i in range(8)]
            for c in range(grid.GetNumberOfCells())]


def cell_volumes(grid, x, u, path):
    """Each cell's rest volume (its corners: the cells are not curved at
    rest) and deformed volume (None unless every cell is a trilinear
    hexahedron, whose deformed volume its corners give), x the rest
    positions."""
    linear = all(grid.GetCellType(c) == vtk.VTK_HEXAHEDRON
                 for c in range(grid.GetNumberOfCells()))
    rest, deformed = [], []
    for c, ids in enumerate(corner_ids(grid)):
        if grid.GetCellType(c) not in (vtk.VTK_HEXAHEDRON,
                                       vtk.VTK_LAGRANGE_HEXAHEDRON):
            sys.exit(f"check_indented_block.py: {path}: cell {c} is not a "
                     "hexahedron")
        rest.append(hex_volume(x[ids]))
        deformed.append(hex_volume(x[ids] + u[ids]))
    return np.array(rest), np.array(deformed) if linear else None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("peer")
    parser.add_argument("ours")
    parser.add_argument("--tolerance", type=float, default=1e-6)
    parser.add_argument("--volume", type=float, default=1e-4)
    parser.add_argument("--length", type=float, default=1.0)
    args = parser.parse_args()

    peer = read(args.peer)
    peer_u = array(peer.GetPointData(), "displacement", args.peer) * 1e3
    peer_x = vtk_to_numpy(peer.GetPoints().GetData()) * 1e3 - peer_u
    ours = read(args.ours)
    our_u = array(ours.GetPointData(), "displacement_mm", args.ours)
    our_x = vtk_to_numpy(ours.GetPoints().GetData()) - our_u  # deformed

    scale = 1e4 / args.length  # float32 points: match to 1e-4 of L
    index = {tuple(np.round(p * scale).astype(int)): i
             for i, p in enumerate(our_x)}
    # The cells' corners: DataOut places the inner points of the peer's
    # Lagrange cells (degree 2) by its vertices, not by the displacement.
    corners = sorted({i for ids in corner_ids(peer) for i in ids})
    worst, matched = 0.0, 0
    for p, u in zip(peer_x[corners], peer_u[corners]):
        i = index.get(tuple(np.round(p * scale).astype(int)))
        if i is None:
            sys.exit(f"check_indented_block.py: the peer's vertex {p} mm is "
                     "not a vertex of ours (the same mesh?)")
        worst = max(worst, np.linalg.norm(our_u[i] - u))
        matched += 1
    top = index[(0, int(round(args.length * scale)), 0)]
    top_peer = [u[1] for p, u in zip(peer_x, peer_u)
                if np.allclose(p, (0, args.length, 0), atol=1e-6 * args.length)]
    rest, deformed = cell_volumes(ours, our_x, our_u, args.ours)
    volumes = []
    if deformed is not None:
        volumes.append(("ours", deformed.sum() / rest.sum() - 1))
    J = array(ours.GetCellData(), "volume_ratio", args.ours)
    field_volume = (J * rest).sum() / rest.sum() - 1
    peer_volume = array(peer.GetPointData(), "dilatation", args.peer).mean() - 1

    print(f"nodal displacement: largest difference {worst:.3e} mm over "
          f"{matched} peer points (largest |u| "
          f"{np.linalg.norm(peer_u, axis=1).max():.6f} mm)")
    print(f"top centre u_y: ours {our_u[top][1]:.8f} mm, step-44 "
          f"{top_peer[0]:.8f} mm")
    volumes += [("ours, field", field_volume), ("step-44", peer_volume)]
    print("volume change v/V0 - 1: " + ", ".join(
        f"{name} {value:.3e}" for name, value in volumes) +
        " (ours: from the displacement of trilinear cells, and the "
        "volume_ratio field; step-44: its dilatation field)")
    failed = worst > args.tolerance
    for name, value in volumes:
        failed = failed or abs(value) > args.volume
    if failed:
        print(f"FAIL: tolerance {args.tolerance} mm, volume {args.volume}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
