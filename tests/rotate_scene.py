"""Turn the block of tests/scenes/block_on_floor.prm and its floor by 90
degrees about the x axis, (x, y, z) -> (x, -z, y): the mesh (gmsh, read
with meshio) as a VTU with the cell array 'label', the floor as OFF.

usage: rotate_scene.py MESH.msh FLOOR.off OUT_DIRECTORY
"""
import os
import sys

import meshio
import numpy as np


def turn(points):
    p = np.asarray(points, dtype=float)
    return np.column_stack([p[:, 0], -p[:, 2], p[:, 1]])


def main():
    mesh_file, floor_file, out = sys.argv[1:4]
    mesh = meshio.read(mesh_file)
    cells = [(block.type, block.data) for block in mesh.cells
             if block.type == "tetra"]
    labels = [np.asarray(data, dtype=np.int32) for block, data in
              zip(mesh.cells, mesh.cell_data["gmsh:physical"])
              if block.type == "tetra"]
    meshio.write(os.path.join(out, "block_turned.vtu"),
                 meshio.Mesh(turn(mesh.points), cells,
                             cell_data={"label": labels}))
    with open(floor_file) as f:
        words = f.read().split()
    n_vertices, n_faces = int(words[1]), int(words[2])
    vertices = np.array(words[4:4 + 3 * n_vertices], dtype=float).reshape(-1, 3)
    faces = words[4 + 3 * n_vertices:]
    with open(os.path.join(out, "floor_turned.off"), "w") as f:
        f.write("OFF\n%d %d 0\n" % (n_vertices, n_faces))
        for v in turn(vertices):
            f.write("%.17g %.17g %.17g\n" % tuple(v))
        for i in range(n_faces):
            f.write(" ".join(faces[4 * i:4 * i + 4]) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
