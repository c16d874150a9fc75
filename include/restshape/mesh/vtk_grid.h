// The parts of a VTK unstructured grid that make a mesh, shared by the
// readers of legacy (.vtk) and XML (.vtu) files.
#ifndef restshape_mesh_vtk_grid_h
#define restshape_mesh_vtk_grid_h

#include <deal.II/base/point.h>

#include <restshape/mesh/mesh_description.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace RestShape
{
  /// Points (m), cells (point numbers per cell), VTK cell types and the
  /// cell-data arrays with one value per cell.
  struct VtkGrid
  {
    std::vector<dealii::Point<3>>            points;
    std::vector<std::vector<long>>           cells;
    std::vector<long>                        types;
    std::map<std::string, std::vector<long>> arrays;
  };

  /**
   * The name of the label array among the cell-data @p arrays: label,
   * labels, MaterialID, material_id, gmsh:physical, CellEntityIds or
   * region (the first found), else the only array; otherwise @p fail is
   * called with a message that lists the arrays.
   */
  std::string
  vtk_label_array(const std::map<std::string, std::vector<long>> &arrays,
                  const std::function<void(const std::string &)> &fail);

  /**
   * The mesh of @p grid: linear tetrahedra (VTK type 10) and hexahedra (12)
   * with their labels, other 3d cells refused, lower-dimensional cells
   * ignored, then the checks of every mesh reader. Errors are InputErrors
   * naming @p file and @p parameter and ending "expected @p format".
   */
  MeshDescription
  vtk_grid_to_mesh(const VtkGrid     &grid,
                   const std::string &file,
                   const std::string &parameter,
                   const std::string &format);
} // namespace RestShape

#endif
