#!/usr/bin/env python3
"""Write tests/data/column_tet.vtk (the column of meshes/column_tet.msh as a
VTK legacy grid, labels in the cell array 'label') as VTK XML unstructured
grids, by VTK's own writer (Debian's python3-vtk9), in the encodings users
meet: ASCII; inline base64 compressed with zlib (32-bit headers); appended
raw data, zlib, 64-bit headers (ParaView's default); appended base64,
uncompressed. Run from the repository root; the scenes
tests/scenes/column_vtu*.prm check that each gives the answer of the .msh."""
import vtk

reader = vtk.vtkUnstructuredGridReader()
reader.SetFileName("tests/data/column_tet.vtk")
reader.ReadAllScalarsOn()
reader.Update()
grid = reader.GetOutput()

def write(name, mode, compress, header64, encode=True):
    writer = vtk.vtkXMLUnstructuredGridWriter()
    writer.SetFileName("tests/data/" + name)
    writer.SetInputData(grid)
    getattr(writer, "SetDataModeTo" + mode)()
    if compress:
        writer.SetCompressorTypeToZLib()
    else:
        writer.SetCompressorTypeToNone()
    if header64:
        writer.SetHeaderTypeToUInt64()
    else:
        writer.SetHeaderTypeToUInt32()
    writer.SetEncodeAppendedData(encode)
    writer.Write()

write("column_tet_ascii.vtu", "Ascii", False, False)
write("column_tet_base64_zlib.vtu", "Binary", True, False)
write("column_tet_raw_zlib64.vtu", "Appended", True, True, encode=False)
write("column_tet_appended_base64.vtu", "Appended", False, False)
