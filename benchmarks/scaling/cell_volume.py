"""Volume ratio J = det F and von Mises stress per cell of a RestShape VTU.

usage: python3 benchmarks/scaling/cell_volume.py SOLUTION.vtu [N]

Reads a deal.II VTU written by RestShape with P1 tetrahedra (4 points per
cell, on the deformed geometry, with the point field displacement_<unit>
and the cell data von_mises_Pa and label, one value per cell), computes J of every cell from its
deformed and rest volumes, and prints one line: the number of cells, the
smallest J, the 1st percentile and median of J, the largest and 99th
percentile von Mises stress (Pa); then the N (default 5) most compressed
cells with their rest-shape centroid (mesh unit) and label.
Needs numpy (apt-get install python3-numpy).
"""
import base64
import re
import struct
import sys
import zlib

import numpy as np


def data_arrays(text):
    """Yield (name, array) for every binary (zlib) DataArray of the file."""
    pattern = r'<DataArray type="(\w+)"([^>]*)format="binary">\s*(\S+)\s*</DataArray>'
    types = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "Int64": "<i8", "UInt8": "u1"}
    for typ, attributes, data in re.findall(pattern, text):
        # Header (base64 on its own): n_blocks, block size, last block size,
        # then the compressed size of each block.
        n_blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
        header_chars = ((4 * (3 + n_blocks) + 2) // 3) * 4
        sizes = struct.unpack("<%dI" % (3 + n_blocks), base64.b64decode(data[:header_chars]))
        raw, offset, values = base64.b64decode(data[header_chars:]), 0, b""
        for size in sizes[3:]:
            values += zlib.decompress(raw[offset:offset + size])
            offset += size
        array = np.frombuffer(values, dtype=types[typ])
        components = re.search(r'NumberOfComponents="(\d+)"', attributes)
        if components:
            array = array.reshape(-1, int(components.group(1)))
        name = re.search(r'Name="([^"]+)"', attributes)
        yield (name.group(1) if name else "points"), array


def tet_volumes(points):
    p = points.reshape(-1, 4, 3)
    return np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0]) / 6


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    arrays = dict(data_arrays(open(sys.argv[1]).read()))
    shown = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    displacement = [k for k in arrays if k.startswith("displacement")]
    if not displacement or "von_mises_Pa" not in arrays:
        sys.exit(sys.argv[1] + ": expected the fields displacement_<unit> and von_mises_Pa")
    x = arrays["points"].astype(float)
    if len(x) % 4:
        sys.exit(sys.argv[1] + ": expected P1 tetrahedra (4 points per cell)")
    rest = x - arrays[displacement[0]].astype(float)
    J = tet_volumes(x) / tet_volumes(rest)
    mises = arrays["von_mises_Pa"].ravel()
    print("cells %d, J min %.4f, 1%% %.4f, median %.4f; von Mises max %.1f Pa, 99%% %.1f Pa"
          % (len(J), J.min(), np.percentile(J, 1), np.median(J), mises.max(), np.percentile(mises, 99)))
    centroids = rest.reshape(-1, 4, 3).mean(axis=1)
    labels = arrays["label"].ravel() if "label" in arrays else None
    for i in np.argsort(J)[:shown]:
        print("  J %.4f at (%.1f, %.1f, %.1f), label %s"
              % (J[i], *centroids[i], "?" if labels is None else "%d" % labels[i]))


if __name__ == "__main__":
    main()
