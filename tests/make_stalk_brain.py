#!/usr/bin/env python3
"""A synthetic segmentation as a user brings it (ITK-SNAP-like labels 10,
42 and 1000 on a 1 mm grid): an ellipsoid brain of 140 x 170 x 120 mm (10
left, 42 right hemisphere) held only by a 12 mm stalk (1000) below it, and
a segmented skull mask whose cavity lies 2 mm outside the brain but cuts
1 mm into it at the top. No tethers: what holds the brain is the stalk and
the skull.

usage: make_stalk_brain.py OUTPUT_DIRECTORY
writes OUTPUT_DIRECTORY/stalk_brain.nii.gz and stalk_skull.nii.gz (uint8
labels; 1000 does not fit a byte, so the labels image is int16).
"""
import gzip
import struct
import sys

A, B, C = 70.0, 85.0, 60.0  # brain semi-axes (mm)
STALK_R, STALK_Y, STALK_BOTTOM = 6.0, -10.0, -80.0  # stalk (mm)
GAP, CUT, BONE = 2.0, 1.0, 4.0  # skull gap, cut at the top, thickness (mm)
NX, NY, NZ = 160, 190, 166  # 1 mm voxels
ORIGIN = (-80.0, -95.0, -96.0)  # world position of voxel (0, 0, 0) (mm)


def in_ellipsoid(x, y, z, a, b, c):
    return (x / a) ** 2 + (y / b) ** 2 + (z / c) ** 2 <= 1.0


def in_stalk(x, y, z, r, bottom):
    return (x * x + (y - STALK_Y) ** 2 <= r * r) and bottom <= z <= 0.0


def brain_label(x, y, z):
    if in_ellipsoid(x, y, z, A, B, C):
        return 10 if x < 0 else 42
    if in_stalk(x, y, z, STALK_R, STALK_BOTTOM):
        return 1000
    return 0


def in_cavity(x, y, z):
    # 2 mm outside the brain, but 1 mm inside it at the top (z > 40 mm).
    top = z > 40.0
    c = C - CUT if top else C + GAP
    return in_ellipsoid(x, y, z, A + GAP, B + GAP, c) or in_stalk(
        x, y, z, STALK_R + GAP, STALK_BOTTOM - GAP)


def is_bone(x, y, z):
    if in_cavity(x, y, z):
        return False
    return in_ellipsoid(x, y, z, A + GAP + BONE, B + GAP + BONE,
                        C + GAP + BONE) or in_stalk(
                            x, y, z, STALK_R + GAP + BONE,
                            STALK_BOTTOM - GAP - BONE)


def write_nifti(path, values, datatype, bitpix):
    """NIfTI-1 with an sform: voxel (i, j, k) at ORIGIN + (i, j, k) mm."""
    header = bytearray(352)
    struct.pack_into("<i", header, 0, 348)
    struct.pack_into("<8h", header, 40, 3, NX, NY, NZ, 1, 1, 1, 1)
    struct.pack_into("<hh", header, 70, datatype, bitpix)
    struct.pack_into("<8f", header, 76, 1, 1, 1, 1, 1, 1, 1, 1)
    struct.pack_into("<f", header, 108, 352.0)  # vox_offset
    struct.pack_into("<f", header, 112, 1.0)  # scl_slope
    struct.pack_into("<B", header, 123, 10)  # xyzt_units: mm, s
    struct.pack_into("<hh", header, 252, 0, 1)  # qform 0, sform aligned
    struct.pack_into("<4f", header, 280, 1, 0, 0, ORIGIN[0])
    struct.pack_into("<4f", header, 296, 0, 1, 0, ORIGIN[1])
    struct.pack_into("<4f", header, 312, 0, 0, 1, ORIGIN[2])
    header[344:348] = b"n+1\0"
    fmt = "<%d%s" % (len(values), "h" if bitpix == 16 else "B")
    with gzip.open(path, "wb", compresslevel=1) as f:
        f.write(bytes(header))
        f.write(struct.pack(fmt, *values))


def main():
    out = sys.argv[1]
    labels, bone = [], []
    for k in range(NZ):
        z = ORIGIN[2] + k
        for j in range(NY):
            y = ORIGIN[1] + j
            for i in range(NX):
                x = ORIGIN[0] + i
                labels.append(brain_label(x, y, z))
                bone.append(1 if is_bone(x, y, z) else 0)
    write_nifti(out + "/stalk_brain.nii.gz", labels, 4, 16)
    write_nifti(out + "/stalk_skull.nii.gz", bone, 2, 8)


if __name__ == "__main__":
    main()
