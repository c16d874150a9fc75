#!/usr/bin/python3
"""A block of N x N x N hexahedra (gmsh 2.2 ASCII), one label (1): the cube
[0, L]^3, the eighth of step-44's indented block (Reese, Wriggers and Reddy
2000) when L = 1 mm. Corner nodes on the planes x, y, z = 0 and = L lie on
them exactly, for Boundary conditions/Fixed boundary planes.

--distort A moves every node by up to A times the cell size in each
coordinate that does not lie on the cube's boundary (interior nodes in
every direction, face nodes within their face, edge nodes along their
edge; the corners stay), from a fixed seed: the distorted patch of a patch
test, whose faces stay planar. A < 0.5 keeps every cell valid.
--tetrahedra splits every hexahedron into 6 tetrahedra along its diagonal
from the smallest to the largest corner (Kuhn's split, conforming).

usage: make_block.py OUT.msh [N [L]] [--distort A] [--tetrahedra]
       (defaults 8 1, mm)"""
import itertools
import random
import sys

SEED = 20000  # the distortion's seed: the same file every time


def arguments():
    args = sys.argv[1:]
    distort, tetrahedra = 0.0, False
    if "--tetrahedra" in args:
        args.remove("--tetrahedra")
        tetrahedra = True
    if "--distort" in args:
        i = args.index("--distort")
        distort = float(args[i + 1])
        del args[i:i + 2]
    if not args:
        sys.exit(__doc__)
    n = int(args[1]) if len(args) > 1 else 8
    length = float(args[2]) if len(args) > 2 else 1.0
    if n < 1 or not length > 0 or not 0 <= distort < 0.5:
        sys.exit("make_block.py: expected N >= 1, L > 0 and 0 <= A < 0.5")
    return args[0], n, length, distort, tetrahedra


def coordinates(n, length, distort):
    rng = random.Random(SEED)
    h = length / n
    points = {}
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                p = []
                for index in (i, j, k):
                    shift = rng.uniform(-distort, distort) * h
                    p.append(length * index / n + (shift if 0 < index < n else 0.0))
                points[(i, j, k)] = p
    return points


def volume(a, b, c, d):
    u = [b[m] - a[m] for m in range(3)]
    v = [c[m] - a[m] for m in range(3)]
    w = [d[m] - a[m] for m in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def cells(n, points, tetrahedra):
    """(gmsh type, node keys) of every cell."""
    for k in range(n):
        for j in range(n):
            for i in range(n):
                if not tetrahedra:
                    yield 5, [(i, j, k), (i + 1, j, k), (i + 1, j + 1, k), (i, j + 1, k),
                              (i, j, k + 1), (i + 1, j, k + 1), (i + 1, j + 1, k + 1),
                              (i, j + 1, k + 1)]
                    continue
                for order in itertools.permutations(range(3)):
                    corner = [i, j, k]
                    path = [tuple(corner)]
                    for axis in order:
                        corner[axis] += 1
                        path.append(tuple(corner))
                    if volume(*[points[p] for p in path]) < 0:
                        path[2], path[3] = path[3], path[2]
                    yield 4, path


def main():
    out, n, length, distort, tetrahedra = arguments()
    points = coordinates(n, length, distort)
    number = {key: m + 1 for m, key in enumerate(sorted(points, key=lambda t: t[::-1]))}
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$Nodes", str(len(points))]
    for key in sorted(points, key=lambda t: t[::-1]):
        lines.append(f"{number[key]} " + " ".join(repr(x) for x in points[key]))
    elements = list(cells(n, points, tetrahedra))
    lines += ["$EndNodes", "$Elements", str(len(elements))]
    for e, (kind, keys) in enumerate(elements, 1):
        lines.append(f"{e} {kind} 2 1 1 " + " ".join(str(number[key]) for key in keys))
    lines += ["$EndElements"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
