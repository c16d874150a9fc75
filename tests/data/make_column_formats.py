#!/usr/bin/env python3
"""Write meshes/column_tet.msh (gmsh 2.2 ASCII, labels 1 and 2) as a VTK
legacy grid (file version 3.0 and 5.1) and an Abaqus input file with element
sets 'body' (label 1) and 'base' (label 2), for the scenes that check that
every format gives the same answer (tests/scenes/column_vtk*.prm,
column_inp.prm). Run from the repository root."""
import re

text = open("meshes/column_tet.msh").read()
nodes_block = text.split("$Nodes\n")[1].split("$EndNodes")[0].split("\n")[1:]
nodes = {}
for line in nodes_block:
    if line.strip():
        n, x, y, z = line.split()
        nodes[int(n)] = (x, y, z)
elements_block = text.split("$Elements\n")[1].split("$EndElements")[0].split("\n")[1:]
tets = []
for line in elements_block:
    p = line.split()
    if len(p) > 1 and p[1] == "4":
        n_tags = int(p[2])
        label = int(p[3])
        tets.append((label, [int(v) for v in p[3 + n_tags:]]))
order = sorted(nodes)
index = {n: i for i, n in enumerate(order)}

def vtk(version):
    out = ["# vtk DataFile Version %s" % version, "column_tet.msh", "ASCII",
           "DATASET UNSTRUCTURED_GRID", "POINTS %d double" % len(order)]
    out += [" ".join(nodes[n]) for n in order]
    if version == "3.0":
        out.append("CELLS %d %d" % (len(tets), 5 * len(tets)))
        out += ["4 " + " ".join(str(index[v]) for v in t) for _, t in tets]
    else:
        out.append("CELLS %d %d" % (len(tets) + 1, 4 * len(tets)))
        out.append("OFFSETS vtktypeint64")
        out += [str(4 * c) for c in range(len(tets) + 1)]
        out.append("CONNECTIVITY vtktypeint64")
        out += [" ".join(str(index[v]) for v in t) for _, t in tets]
    out.append("CELL_TYPES %d" % len(tets))
    out += ["10"] * len(tets)
    out += ["CELL_DATA %d" % len(tets), "SCALARS quality double 1",
            "LOOKUP_TABLE default"] + ["1"] * len(tets)
    out += ["SCALARS label int 1", "LOOKUP_TABLE default"]
    out += [str(label) for label, _ in tets]
    return "\n".join(out) + "\n"

open("tests/data/column_tet.vtk", "w").write(vtk("3.0"))
open("tests/data/column_tet_v51.vtk", "w").write(vtk("5.1"))

inp = ["*Heading", "** meshes/column_tet.msh as Abaqus input", "*Node"]
inp += ["%d, %s" % (n, ", ".join(nodes[n])) for n in order]
names = {1: "body", 2: "base"}
for label in (1, 2):
    inp.append("*Element, type=C3D4, elset=%s" % names[label])
    inp += ["%d, %s" % (e + 1, ", ".join(str(v) for v in t))
            for e, (l, t) in enumerate(tets) if l == label]
open("tests/data/column_tet.inp", "w").write("\n".join(inp) + "\n")
