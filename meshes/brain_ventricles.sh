#!/bin/bash
# The brain with lateral ventricles of prm/brain_ventricles.prm: the
# labelled brain of meshes/brain.sh (meshes/brain_labels.nii.gz) with its
# ventricles as cavities (meshes/brain_ventricles.py: dark voxels of
# Colin27's T1 deep in the cerebrum), meshed with restshape-mesh; the skull
# 2 mm outside the brain; sulci narrower than about 4 mm closed (--close-sulci
# 2: 119 pinched edges without). Run from the repository root after building;
# needs python3-nibabel and python3-scipy.
#
#   meshes/brain_ventricles.sh [OUTPUT_DIR]
#
# Writes OUTPUT_DIR/brain_ventricles.nii.gz, brain_ventricles.msh (labels
# 1 cerebrum, 2 tumour, 3 cerebellum, 4 brainstem; physical surfaces 1
# outer_surface, 2 cavity_walls) and brain_ventricles_skull.off.
set -e
out=${1:-meshes}
build=${BUILD:-build}
mkdir -p "$out"
/usr/bin/python3 meshes/brain_ventricles.py "$out/brain_ventricles.nii.gz"
"$build"/restshape-mesh --image "$out/brain_ventricles.nii.gz" \
  --label-names meshes/brain_names.txt \
  --cell-size 6 --facet-size 6 --facet-distance 1 --close-sulci 2 \
  --skull-out "$out/brain_ventricles_skull.off" --skull-gap 2 --skull-facet-size 5 \
  --out "$out/brain_ventricles.msh"
