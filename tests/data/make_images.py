#!/usr/bin/env python3
# Writes the small NIfTI-1 test images of tests/data (no dependencies):
#   sphere_labels.nii  24^3 voxels of 2 mm, x mirrored by the sform, origin
#                      shifted: label 1 a ball of radius 18 mm around
#                      (16, 4, 34) mm, label 2 a ball of radius 8 mm inside it
#   empty_labels.nii   8^3 voxels, all 0
#   atlas_int16.nii    the sphere as int16 with atlas-like labels above 255:
#                      300 for the outer ball, 2035 for the inner one
#   negative_label.nii int16, 8^3 voxels, label 5 with one voxel -3
#   fractional_label.nii float32, 8^3 voxels, label 2 with one voxel 1.5
#   skull_shell.nii    a segmented skull for sphere_labels.nii: on a grid of
#                      28^3 voxels of 2 mm (identity map, origin shifted), bone
#                      between 22 and 27 mm from the ball's centre, a cavity
#                      inside (the ball's 18 mm radius 4 mm within it)
#   skull_open.nii     the same shell with a 12 mm hole (no cavity)
#   zero_voxel.nii     8^3 voxels, qform only, pixdim[2] = 0 (libnifti's
#                      qform makes it 1 mm)
#   nan_voxel_size.nii the same with pixdim[3] = NaN
#   nan_label.nii      float32, 8^3 voxels, label 2 with one voxel NaN
#   border_cube.nii    10^3 voxels of 1 mm, every one label 1: the mesh must
#                      keep the outer half voxel (1000 mm^3, not 729)
#   enclosed.nii.gz    64^3 voxels of 2 mm: label 3 a ball of radius 60 mm
#                      holding a void (label 0) of radius 10 mm and a ball of
#                      label 250 of radius 10 mm, each 25 mm off the centre
import gzip
import math
import struct

TYPES = {'uint8': (2, 8, 'B'), 'int16': (4, 16, 'h'), 'float32': (16, 32, 'f')}

def write(path, n, spacing, srow, values, kind='uint8', qform_pixdim=None):
    code, bits, fmt = TYPES[kind]
    h = bytearray(348)
    struct.pack_into('<i', h, 0, 348)
    struct.pack_into('<8h', h, 40, 3, n, n, n, 1, 1, 1, 1)
    struct.pack_into('<hh', h, 70, code, bits)
    pixdim = qform_pixdim or (spacing, spacing, spacing)
    struct.pack_into('<8f', h, 76, 1, *pixdim, 1, 1, 1, 1)
    struct.pack_into('<f', h, 108, 352)
    struct.pack_into('<f', h, 112, 1)
    h[123] = 2  # mm
    if qform_pixdim:
        struct.pack_into('<hh', h, 252, 1, 0)  # qform scanner, no sform
    else:
        struct.pack_into('<hh', h, 252, 0, 2)  # qform 0, sform aligned
        for r in range(3):
            struct.pack_into('<4f', h, 280 + 16 * r, *srow[r])
    h[344:348] = b'n+1\0'
    data = h + bytes(4) + struct.pack('<%d%s' % (len(values), fmt), *values)
    if path.endswith('.gz'):
        data = gzip.compress(data, mtime=0)
    with open(path, 'wb') as f:
        f.write(data)

n, s = 24, 2.0
srow = [[-s, 0, 0, 40.0], [0, s, 0, -20.0], [0, 0, s, 10.0]]
centre = (16.0, 4.0, 34.0)
values = []
for k in range(n):
    for j in range(n):
        for i in range(n):
            x = (srow[0][0] * i + srow[0][3], srow[1][1] * j + srow[1][3], srow[2][2] * k + srow[2][3])
            r = sum((x[d] - centre[d]) ** 2 for d in range(3)) ** 0.5
            values.append(2 if r <= 8 else 1 if r <= 18 else 0)
write('tests/data/sphere_labels.nii', n, s, srow, values)
write('tests/data/empty_labels.nii', 8, 1.0, [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]], [0] * 512)
write('tests/data/atlas_int16.nii', n, s, srow,
      [{0: 0, 1: 300, 2: 2035}[v] for v in values], 'int16')
small = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]
block = [5] * 512
block[3 + 8 * (2 + 8 * 1)] = -3
write('tests/data/negative_label.nii', 8, 1.0, small, block, 'int16')
block = [2.0] * 512
block[7] = 1.5
write('tests/data/fractional_label.nii', 8, 1.0, small, block, 'float32')

m = 28
shell_srow = [[s, 0, 0, -12.0], [0, s, 0, -24.0], [0, 0, s, 6.0]]
shell, open_shell = [], []
for k in range(m):
    for j in range(m):
        for i in range(m):
            x = (s * i - 12.0, s * j - 24.0, s * k + 6.0)
            r = sum((x[d] - centre[d]) ** 2 for d in range(3)) ** 0.5
            bone = 22 <= r <= 27
            shell.append(1 if bone else 0)
            hole = x[2] - centre[2] > 15 and ((x[0] - centre[0]) ** 2 + (x[1] - centre[1]) ** 2) ** 0.5 < 6
            open_shell.append(1 if bone and not hole else 0)
write('tests/data/skull_shell.nii', m, s, shell_srow, shell)
write('tests/data/skull_open.nii', m, s, shell_srow, open_shell)

write('tests/data/zero_voxel.nii', 8, 1.0, small, [5] * 512, qform_pixdim=(1.0, 0.0, 1.0))
write('tests/data/nan_voxel_size.nii', 8, 1.0, small, [5] * 512, qform_pixdim=(1.0, 1.0, float('nan')))
block = [2.0] * 512
block[9] = float('nan')
write('tests/data/nan_label.nii', 8, 1.0, small, block, 'float32')
write('tests/data/border_cube.nii', 10, 1.0, small, [1] * 1000)

m, s = 64, 2.0
centre = (m - 1) * s / 2
values = []
for k in range(m):
    for j in range(m):
        for i in range(m):
            x = (i * s - centre, j * s - centre, k * s - centre)
            r = math.sqrt(sum(c * c for c in x))
            void = math.dist(x, (-25.0, 0.0, 0.0)) <= 10
            ball = math.dist(x, (25.0, 0.0, 0.0)) <= 10
            values.append(0 if void or r > 60 else 250 if ball else 3)
write('tests/data/enclosed.nii.gz', m, s, [[s, 0, 0, 0], [0, s, 0, 0], [0, 0, s, 0]], values)
