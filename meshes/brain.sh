#!/bin/bash
# The brain of prm/brain.prm from Debian's mricron-data (Colin27 on the MNI
# grid, 1 mm voxels, coordinates in MNI millimetres: x right, y anterior,
# z superior). Run from the repository root after building.
#
#   meshes/brain.sh [coarse|medium|fine|SIZE_MM] [OUTPUT_DIR]
#
# Labels (physical volume tags of the .msh):
#   1 cerebrum, 2 tumour (a 12 mm sphere in the left frontal lobe at MNI
#   (-32, 28, 28)), 3 cerebellum, 4 brainstem.
# Writes OUTPUT_DIR/brain_labels.nii.gz (the labelled image),
# OUTPUT_DIR/brain_<level>.msh and OUTPUT_DIR/brain_skull.off (the inner
# skull surface, 2 mm outside the brain: the CSF layer).
# The coarse mesh (about the paper's size) is committed to meshes/; the finer
# ones are made on demand (benchmarks), with sulci narrower than about 6 mm
# closed (--close-sulci 3, CLOSE_SULCI to change): the surfaces of finer
# meshes otherwise pinch where folds touch, and CSF pressure crushes the
# cells there (doc/brain.md).
set -e
level=${1:-coarse}
out=${2:-meshes}
build=${BUILD:-build}
templates=${MRICRON_TEMPLATES:-/usr/share/mricron/templates}
case $level in
  coarse) size="--cell-size 12 --facet-size 18 --facet-distance 3" ;;
  medium) size="--cell-size 6 --facet-size 8 --facet-distance 1.5" ;;
  fine)   size="--cell-size 3 --facet-size 4 --facet-distance 0.75" ;;
  *)      size="--cell-size $level --facet-size $level --facet-distance 1" ;;
esac
[ "$level" = coarse ] || size="$size --close-sulci ${CLOSE_SULCI:-3}"
mkdir -p "$out"
labels=$out/brain_labels.nii.gz
if [ ! -f "$labels" ]; then
  "$build"/restshape-brain-labels --brain "$templates"/ch2bet.nii.gz \
    --atlas "$templates"/aal.nii.gz --tumour -32,28,28 --tumour-radius 12 \
    --out "$labels"
fi
skull=""
if [ "$level" = coarse ]; then
  skull="--skull-out $out/brain_skull.off --skull-gap 2 --skull-facet-size 5"
fi
"$build"/restshape-mesh --image "$labels" --out "$out/brain_$level.msh" $size $skull
if [ "$level" = coarse ]; then
  # The skull of prm/brain_skull_contact.prm: 0.5 mm from the brain.
  "$build"/restshape-mesh --image "$labels" --out "$out/brain_$level.msh" $size \
    --skull-out "$out/brain_skull_0.5.off" --skull-gap 0.5 --skull-facet-size 5
  # The skull of prm/brain_skull_cut.prm: it cuts 0.5 mm into the brain, as
  # a segmented skull does.
  "$build"/restshape-mesh --image "$labels" --out "$out/brain_$level.msh" $size \
    --skull-out "$out/brain_skull_cut_0.5.off" --skull-gap -0.5 --skull-facet-size 5
fi
