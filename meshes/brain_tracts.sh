#!/bin/bash
# The brain of prm/brain_tracts.prm: the brain of prm/brain.prm (Colin27 and
# AAL from Debian's mricron-data) with a second atlas laid over it, the JHU
# white-matter atlas, through the label map meshes/brain_tracts.map: its
# corpus callosum, internal capsules and corona radiata become tissue 5,
# "tracts". The JHU atlas lies on another grid (182 x 218 x 182 voxels,
# FSL's MNI152) than Colin27 (181 x 217 x 181): its labels are taken at the
# nearest voxel in MNI coordinates. Run from the repository root after
# building:
#
#   meshes/brain_tracts.sh [OUTPUT_DIR]
#
# Writes OUTPUT_DIR/brain_tracts_labels.nii.gz and brain_tracts_names.txt
# (the labelled image and its name table), brain_tracts.msh (8 mm cells,
# sulci narrower than about 6 mm closed; the labels carry their names) and
# brain_tracts_skull.off (the inner skull surface, 2 mm outside the brain).
set -e
out=${1:-meshes}
build=${BUILD:-build}
templates=${MRICRON_TEMPLATES:-/usr/share/mricron/templates}
jhu=$templates/JHU-WhiteMatter-labels-1mm
mkdir -p "$out"
"$build"/restshape-brain-labels --brain "$templates"/ch2bet.nii.gz \
  --atlas "$templates"/aal.nii.gz --tumour -32,28,28 --tumour-radius 12 \
  --overlay "$jhu".nii.gz --overlay-names "$jhu".nii.txt \
  --overlay-map meshes/brain_tracts.map \
  --out "$out"/brain_tracts_labels.nii.gz \
  --names-out "$out"/brain_tracts_names.txt
"$build"/restshape-mesh --image "$out"/brain_tracts_labels.nii.gz \
  --label-names "$out"/brain_tracts_names.txt --out "$out"/brain_tracts.msh \
  --cell-size 8 --facet-size 8 --facet-distance 1.5 --close-sulci 3 \
  --skull-out "$out"/brain_tracts_skull.off --skull-gap 2 --skull-facet-size 5
rm "$out"/brain_tracts_labels.nii.gz
