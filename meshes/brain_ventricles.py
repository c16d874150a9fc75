#!/usr/bin/python3
# The brain of meshes/brain_labels.nii.gz (1 cerebrum, 2 tumour, 3
# cerebellum, 4 brainstem; meshes/brain.sh) with its lateral ventricles as
# cavities (label 0 inside the cerebrum): the two largest connected regions
# of dark voxels (T1 intensity below THRESHOLD in Debian's Colin27,
# ch2bet.nii.gz) at least 12 mm inside the brain, opened and closed by one
# voxel. Needs python3-nibabel and python3-scipy (Debian packages).
#
#   meshes/brain_ventricles.py [OUT.nii.gz] [THRESHOLD]
import sys

import nibabel as nib
import numpy as np
from scipy import ndimage as ndi

out = sys.argv[1] if len(sys.argv) > 1 else 'meshes/brain_ventricles.nii.gz'
threshold = float(sys.argv[2]) if len(sys.argv) > 2 else 45
labels_image = nib.load('meshes/brain_labels.nii.gz')
labels = np.asarray(labels_image.dataobj).astype(np.uint8)
t1 = np.asarray(nib.load('/usr/share/mricron/templates/ch2bet.nii.gz').dataobj, dtype=float)
assert t1.shape == labels.shape, 'the T1 and the labels are on different grids'

inside = ndi.binary_erosion(labels > 0, iterations=12)
dark = ndi.binary_closing(ndi.binary_opening((t1 < threshold) & inside))
regions, n = ndi.label(dark)
sizes = ndi.sum(dark, regions, range(1, n + 1))
ventricles = np.isin(regions, 1 + np.argsort(sizes)[::-1][:2])
ventricles &= labels == 1  # in the cerebrum only
labels[ventricles] = 0
print(f'ventricles: {ventricles.sum() / 1000:.1f} cm^3 in {n} dark regions '
      f'(the two largest: {sorted(sizes)[-1] / 1000:.1f} and {sorted(sizes)[-2] / 1000:.1f} cm^3)')
nib.save(nib.Nifti1Image(labels, labels_image.affine, labels_image.header), out)
