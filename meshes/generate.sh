#!/bin/bash
# Regenerate the structured test meshes of meshes/ (run from the repository
# root after building). Lengths in mm; label 2 marks the clamped part.
set -e
gen=${GRIDGEN:-build/restshape-gridgen}
# Gravity column: 20 x 20 x 50 mm, bottom 10 mm clamped (label 2).
$gen --size 20,20,50 --subdivisions 2,2,5 --slab z:0:10:2 --out meshes/column_tet.msh
$gen --size 20,20,50 --subdivisions 2,2,5 --slab z:0:10:2 --cell-type tetrahedra24 --out meshes/column_tet24.msh
$gen --size 20,20,50 --subdivisions 2,2,5 --slab z:0:10:2 --cell-type hexahedra --out meshes/column_hex.msh
# Cantilever: 100 x 10 x 10 mm, first 10 mm clamped (label 2).
$gen --size 100,10,10 --subdivisions 20,2,2 --slab x:0:10:2 --out meshes/cantilever_tet.msh
# Peeling strip: 100 x 10 x 1 mm, buoyant end 90-100 mm (label 2), rollers
# at 0-5 mm (label 3).
$gen --size 100,10,1 --subdivisions 100,2,1 --slab x:90:100:2 --slab x:0:5:3 --out meshes/strip_tet.msh
# Hertz hemisphere: R = 50 mm, dome down, pole at the origin, graded towards the pole.
$gen --hemisphere 50 --refinements 2 --grading 2 --cell-type hexahedra --out meshes/hemisphere_hex.msh
# Obstacles (closed, outward-oriented surfaces, mm).
surf=${SURFACE:-build/restshape-surface}
$surf --box -20,-20,-10 --size 60,60,10 --out meshes/floor.off
$surf --box -20,-20,50 --size 60,60,10 --out meshes/ceiling.off
$surf --sphere 0,0,50 --radius 50.5 --subdivisions 3 --out meshes/dome_cavity.off
$surf --sphere 0,0,0 --radius 15 --subdivisions 3 --out meshes/opening_pole.off
$surf --box -100,-100,-20 --size 200,200,20 --out meshes/floor_large.off
$surf --box -5,-5,-20 --size 104.5,20,40 --out meshes/cavity_box.off
$surf --box -5,-5,5 --size 30,30,60 --out meshes/column_cut_box.off
$surf --box -10,-10,-10 --size 120,30,10 --out meshes/floor_strip.off
# Lame shell: radii 10 and 20 mm, label 1 a 2 mm inner layer, 4 mm cells
# (gmsh, seeded; tests/data/lame_shell.prm).
/usr/bin/python3 meshes/make_shell.py meshes/shell_4mm.msh 10 20 2 4
