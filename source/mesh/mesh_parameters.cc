// The parameters of subsection Mesh.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/mesh/mesh_parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("File",
                      "meshes/column_tet.msh",
                      Patterns::FileName(),
                      "Mesh file: gmsh (.msh, any version; physical volume "
                      "tags are the labels, $PhysicalNames their names), "
                      "VTK legacy ASCII unstructured grid (.vtk) or VTK XML "
                      "unstructured grid (.vtu; labels from the cell-data "
                      "array label or MaterialID) or "
                      "Abaqus (.inp; C3D4/C3D8 elements, element sets "
                      "numbered 1, 2, ... in order are the labels, their "
                      "names the names). Linear tetrahedra or hexahedra. "
                      "The labels are used by Materials, Boundary "
                      "conditions, Loads and Contact. Relative paths are "
                      "relative to the working directory.");
    prm.declare_entry("Length unit",
                      "mm",
                      Patterns::Selection("mm|m"),
                      "Unit of the coordinates in the mesh file. Internally "
                      "everything is SI; outputs use this unit for lengths.");
    prm.declare_entry("Rest shape file",
                      "",
                      Patterns::Anything(),
                      "Optional: a gmsh file with the same cells and vertices "
                      "as Mesh/File (e.g. the rest_shape.msh of an inverse "
                      "run) whose vertex positions are the stress-free shape. "
                      "The simulation then starts pre-stressed: the body "
                      "rests in that shape and the loads bring it back to "
                      "Mesh/File's geometry. Empty: Mesh/File is stress-free.");
    prm.declare_entry("Label names",
                      "",
                      Patterns::Anything(),
                      "Optional: a table of 'label name' lines (e.g. the "
                      ".nii.txt table of an atlas) that names the labels "
                      "of Mesh/File, in addition to its own gmsh "
                      "$PhysicalNames (which restshape-mesh writes). Every "
                      "label list of the scene (Materials, Boundary "
                      "conditions, Loads, Contact) accepts these names "
                      "where it accepts a label, e.g. 'cerebrum:1500'.");
    prm.declare_entry("Cell type",
                      "tetrahedra",
                      Patterns::Selection("tetrahedra|hexahedra"),
                      "tetrahedra: use the tetrahedra of the file. "
                      "hexahedra: split every tetrahedron into four "
                      "hexahedra (edge midpoints, face centroids, centroid), "
                      "keeping labels; a hexahedral file is used as is.");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 8),
                      "Number of uniform refinements of the mesh (each "
                      "splits every cell into 8).");
    prm.leave_subsection();
  }

  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    file = prm.get("File");
    if (file.empty())
      throw InputError("", "Mesh/File", "no mesh file given");
    rest_shape_file  = dealii::Utilities::trim(prm.get("Rest shape file"));
    label_names_file = dealii::Utilities::trim(prm.get("Label names"));
    length_unit_name = prm.get("Length unit");
    length_unit = length_unit_in_metres(length_unit_name, "Mesh/Length unit");
    cell_type   = prm.get("Cell type") == "hexahedra" ? CellType::hexahedra :
                                                        CellType::tetrahedra;
    global_refinements = prm.get_integer("Global refinements");
    prm.leave_subsection();
  }
} // namespace RestShape
