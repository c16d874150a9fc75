// Subsection "Mesh": the mesh file, its length unit and refinement.
#ifndef restshape_mesh_mesh_parameters_h
#define restshape_mesh_mesh_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace RestShape
{
  /// The parameter that names the mesh file, for error messages.
  inline const std::string mesh_file_parameter = "Mesh/File";

  enum class CellType
  {
    tetrahedra,
    hexahedra
  };

  struct MeshParameters
  {
    std::string  file;
    std::string  rest_shape_file;  // optional: the rest shape (same mesh)
    std::string  label_names_file; // optional: "label name" table
    std::string  length_unit_name; // "mm" or "m"
    double       length_unit;      // metres per unit of the file
    CellType     cell_type;
    unsigned int global_refinements;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
