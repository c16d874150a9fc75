#!/usr/bin/python3
"""Write the CalculiX input of the cantilever's forward solve from our mesh.

usage: msh_to_inp.py MESH.msh OUT.inp FIXED_LABEL

The mesh (gmsh, lengths in mm, as restshape-gridgen writes it) is read
with meshio. Each linear tetrahedron becomes a C3D10 element whose
mid-edge nodes sit on the straight edges: the same quadratic space as our
P2 tetrahedra on the same mesh, so both solve for the same DoFs. Lengths
are written in metres, so the material and the load are in SI units: the
values of prm/cantilever.prm (E = 1e5 Pa, nu = 0.3, rho = 1000 kg/m^3,
gravity 9.81 m/s^2 along -z), the St. Venant-Kirchhoff law that CalculiX
uses for *ELASTIC with NLGEOM. Every node of the cells with FIXED_LABEL is
clamped, as "Boundary conditions/Fixed labels" does.
"""
import sys

import meshio
import numpy

MM_TO_M = 1e-3
# Abaqus/CalculiX C3D10: corners 1-4, then the mid-edge nodes of the edges
# 1-2, 2-3, 3-1, 1-4, 2-4, 3-4.
C3D10_EDGES = ((0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3))


def read_tetrahedra(path, fixed_label):
    mesh = meshio.read(path)
    cells = []
    labels = []
    for block, data in zip(mesh.cells, mesh.cell_data["gmsh:physical"]):
        if block.type == "tetra":
            cells.append(block.data)
            labels.append(data)
    if not cells:
        sys.exit(f"{path}: no tetrahedra")
    cells = numpy.concatenate(cells)
    fixed = numpy.concatenate(labels) == fixed_label
    return mesh.points * MM_TO_M, cells, fixed


def positively_oriented(points, cells):
    a, b, c, d = (points[cells[:, i]] for i in range(4))
    volume = numpy.einsum("ij,ij->i", numpy.cross(b - a, c - a), d - a)
    cells = cells.copy()
    flip = volume < 0
    cells[flip, 1], cells[flip, 2] = cells[flip, 2], cells[flip, 1].copy()
    return cells


def quadratic(points, cells):
    """Mid-edge nodes, one per edge shared by its cells."""
    edge_node = {}
    new_points = list(points)
    elements = numpy.empty((len(cells), 10), dtype=int)
    for k, cell in enumerate(cells):
        elements[k, :4] = cell
        for j, (p, q) in enumerate(C3D10_EDGES):
            key = (min(cell[p], cell[q]), max(cell[p], cell[q]))
            if key not in edge_node:
                edge_node[key] = len(new_points)
                new_points.append(0.5 * (points[key[0]] + points[key[1]]))
            elements[k, 4 + j] = edge_node[key]
    return numpy.array(new_points), elements


def write_lines(out, keyword, rows):
    out.write(keyword + "\n")
    for row in rows:
        out.write(", ".join(str(v) for v in row) + "\n")


def write_inp(path, points, elements, fixed):
    fixed_nodes = numpy.unique(elements[fixed]) + 1
    with open(path, "w") as out:
        out.write("*HEADING\nCantilever under its own weight (RestShape peer benchmark)\n")
        write_lines(out, "*NODE, NSET=Nall",
                    ((i + 1, *("%.12g" % x for x in p)) for i, p in enumerate(points)))
        write_lines(out, "*ELEMENT, TYPE=C3D10, ELSET=Eall",
                    ((k + 1, *(e + 1)) for k, e in enumerate(elements)))
        write_lines(out, "*NSET, NSET=Fixed",
                    (fixed_nodes[i:i + 8] for i in range(0, len(fixed_nodes), 8)))
        out.write("*MATERIAL, NAME=Tissue\n*ELASTIC\n1e5, 0.3\n*DENSITY\n1000.\n")
        out.write("*SOLID SECTION, ELSET=Eall, MATERIAL=Tissue\n")
        out.write("*BOUNDARY\nFixed, 1, 3\n")
        out.write("*STEP, NLGEOM, INC=1000\n*STATIC\n1., 1.\n")
        out.write("*DLOAD\nEall, GRAV, 9.81, 0., 0., -1.\n")
        out.write("*NODE PRINT, NSET=Nall\nU\n*END STEP\n")


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    points, cells, fixed = read_tetrahedra(sys.argv[1], int(sys.argv[3]))
    cells = positively_oriented(points, cells)
    points, elements = quadratic(points, cells)
    write_inp(sys.argv[2], points, elements, fixed)
    print(f"{sys.argv[2]}: {len(elements)} C3D10 elements, {len(points)} nodes, "
          f"{3 * len(points)} DoFs")


main()
