#!/usr/bin/python3
"""A block of N x N x N hexahedra (gmsh 2.2 ASCII), one label (1): the cube
[0, L]^3, the eighth of step-44's indented block (Reese, Wriggers and Reddy
2000) when L = 1 mm. Corner nodes on the planes x, y, z = 0 and = L lie on
them exactly, for Boundary conditions/Fixed boundary planes.

usage: make_block.py OUT.msh [N [L]]   (defaults 8 1, mm)"""
import sys


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    length = float(sys.argv[3]) if len(sys.argv) > 3 else 1.0
    if n < 1 or not length > 0:
        sys.exit("make_block.py: expected N >= 1 and L > 0")

    def node(i, j, k):
        return 1 + i + (n + 1) * (j + (n + 1) * k)

    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$Nodes",
             str((n + 1) ** 3)]
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                lines.append(f"{node(i, j, k)} {length * i / n!r} "
                             f"{length * j / n!r} {length * k / n!r}")
    lines += ["$EndNodes", "$Elements", str(n ** 3)]
    element = 0
    for k in range(n):
        for j in range(n):
            for i in range(n):
                element += 1
                corners = [node(i, j, k), node(i + 1, j, k),
                           node(i + 1, j + 1, k), node(i, j + 1, k),
                           node(i, j, k + 1), node(i + 1, j, k + 1),
                           node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
                lines.append(f"{element} 5 2 1 1 " +
                             " ".join(map(str, corners)))
    lines += ["$EndElements"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
