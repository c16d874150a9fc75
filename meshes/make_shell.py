#!/usr/bin/python3
"""A thick spherical shell of tetrahedra (gmsh 2.2 ASCII, mm): inner radius
R1, outer radius R2, label 1 an inner layer of thickness T, label 2 the rest;
its cavity (r < R1) is a closed inner surface. The geometry of the Lame shell
tests (doc/model.md, "Ventricular pressure").

usage: make_shell.py OUT.msh [R1 R2 T H [ORDER]]   (defaults 10 20 2 4 1, mm)"""
import sys

import gmsh


def main():
    out = sys.argv[1]
    r1, r2, t, h = (float(x) for x in (sys.argv[2:6] or (10, 20, 2, 4)))
    order = int(sys.argv[6]) if len(sys.argv) > 6 else 1
    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.RandomSeed", 1)
    gmsh.model.add("shell")
    occ = gmsh.model.occ
    layer = occ.cut([(3, occ.addSphere(0, 0, 0, r1 + t))],
                    [(3, occ.addSphere(0, 0, 0, r1))])[0]
    rest = occ.cut([(3, occ.addSphere(0, 0, 0, r2))],
                   [(3, occ.addSphere(0, 0, 0, r1 + t))])[0]
    occ.fragment(layer, rest)
    occ.synchronize()
    volumes = gmsh.model.getEntities(3)

    def outer_radius(tag):
        x0, y0, z0, x1, y1, z1 = gmsh.model.getBoundingBox(3, tag)
        return max(x1 - x0, y1 - y0, z1 - z0) / 2

    volumes.sort(key=lambda v: outer_radius(v[1]))
    gmsh.model.addPhysicalGroup(3, [volumes[0][1]], 1)
    gmsh.model.addPhysicalGroup(3, [v[1] for v in volumes[1:]], 2)
    gmsh.option.setNumber("Mesh.MeshSizeMin", h)
    gmsh.option.setNumber("Mesh.MeshSizeMax", h)
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.option.setNumber("Mesh.Binary", 0)
    gmsh.model.mesh.generate(3)
    if order > 1:
        gmsh.model.mesh.setOrder(order)
    gmsh.write(out)
    gmsh.finalize()


if __name__ == "__main__":
    main()
