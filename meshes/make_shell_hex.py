#!/usr/bin/python3
"""A thick spherical shell of hexahedra (gmsh 2.2 ASCII, mm), structured as
a cubed sphere: each of the cube's 6 faces an equiangular N x N grid of
directions, radial layers between the radii. Inner radius R1, outer radius
R2, label 1 an inner layer of thickness T, label 2 the rest; its cavity
(r < R1) is a closed inner surface. The hexahedral twin of make_shell.py
(the Lame shell tests, doc/model.md), H the target cell size (mm) at the
layer between the labels.

usage: make_shell_hex.py OUT.msh [R1 R2 T H]   (defaults 10 20 2 4, mm)"""
import math
import sys

import numpy as np


def directions(n):
    """The unit directions of the 6 faces' grids, (6, n+1, n+1, 3)."""
    t = np.tan(np.linspace(-math.pi / 4, math.pi / 4, n + 1))
    a, b = np.meshgrid(t, t, indexing="ij")
    one = np.ones_like(a)
    faces = []
    for axis in range(3):
        for sign in (1, -1):
            v = np.empty(a.shape + (3,))
            v[..., axis] = sign * one
            # a right-handed pair of tangent axes for each face
            u, w = [(axis + 1) % 3, (axis + 2) % 3]
            v[..., u] = a * sign
            v[..., w] = b
            faces.append(v / np.linalg.norm(v, axis=-1, keepdims=True))
    return faces


def radii(r1, r2, t, h):
    inner = max(1, math.ceil(t / h - 1e-9))
    outer = max(1, math.ceil((r2 - r1 - t) / h - 1e-9))
    return (list(np.linspace(r1, r1 + t, inner + 1)) +
            list(np.linspace(r1 + t, r2, outer + 1))[1:]), inner


def main():
    out = sys.argv[1]
    r1, r2, t, h = (float(x) for x in (sys.argv[2:6] or (10, 20, 2, 4)))
    n = max(1, math.ceil(math.pi / 2 * (r1 + t) / h - 1e-9))
    rs, inner_layers = radii(r1, r2, t, h)
    index, points = {}, []

    def node(x):
        key = tuple(np.round(x, 9))
        if key not in index:
            index[key] = len(points)
            points.append(x)
        return index[key] + 1

    cells = []
    for grid in directions(n):
        for k in range(len(rs) - 1):
            for i in range(n):
                for j in range(n):
                    corners = [grid[i, j], grid[i + 1, j], grid[i + 1, j + 1],
                               grid[i, j + 1]]
                    ids = ([node(rs[k] * c) for c in corners] +
                           [node(rs[k + 1] * c) for c in corners])
                    x = np.array([points[m - 1] for m in ids])
                    jac = np.linalg.det(np.array([x[1] - x[0], x[3] - x[0],
                                                  x[4] - x[0]]))
                    if jac < 0:  # keep gmsh's positive orientation
                        ids = ids[4:] + ids[:4]
                    cells.append((1 if k < inner_layers else 2, ids))
    with open(out, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n")
        f.write(f"{len(points)}\n")
        for m, x in enumerate(points, 1):
            f.write(f"{m} {x[0]:.12g} {x[1]:.12g} {x[2]:.12g}\n")
        f.write(f"$EndNodes\n$Elements\n{len(cells)}\n")
        for m, (label, ids) in enumerate(cells, 1):
            f.write(f"{m} 5 2 {label} {label} " + " ".join(map(str, ids)) + "\n")
        f.write("$EndElements\n")


if __name__ == "__main__":
    main()
