"""Reading restshape's VTU and PVTU files with VTK's own XML readers, as
ParaView and VisIt do: shared by the tests' check scripts."""
import vtk


def read_grid(path):
    """The unstructured grid of a .vtu or (under MPI) .pvtu file, or None
    where VTK's reader reports an error."""
    reader = (vtk.vtkXMLPUnstructuredGridReader() if path.endswith('.pvtu')
              else vtk.vtkXMLUnstructuredGridReader())
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode() != 0:
        return None
    return reader.GetOutput()
