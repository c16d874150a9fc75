// Helpers shared by the mesh readers of mesh_formats.h.
#ifndef restshape_mesh_mesh_file_reading_h
#define restshape_mesh_mesh_file_reading_h

#include <deal.II/grid/tria_description.h>

#include <fstream>
#include <string>
#include <vector>

namespace RestShape
{
  namespace MeshFileReading
  {
    /// @p text in lower case (ASCII).
    std::string
    lower(std::string text);

    /// The file open for reading; InputError naming @p parameter if not.
    std::ifstream
    open(const std::string &file, const std::string &parameter);

    /// A cell from its vertex numbers in file order (hexahedra reordered
    /// from the gmsh, VTK and Abaqus order to deal.II's).
    dealii::CellData<3>
    make_cell(const std::vector<unsigned int> &vertices);
  } // namespace MeshFileReading
} // namespace RestShape

#endif
