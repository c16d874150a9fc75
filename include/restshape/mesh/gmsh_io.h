// Reading and writing gmsh meshes.
#ifndef restshape_mesh_gmsh_io_h
#define restshape_mesh_gmsh_io_h

#include <restshape/mesh/mesh_description.h>

#include <array>
#include <functional>
#include <map>
#include <string>

namespace RestShape
{
  /**
   * Read a gmsh file into a description in metres. Throws InputError naming
   * the file and "Mesh/File" for missing, unreadable or malformed files and
   * for meshes that are not purely tetrahedral or purely hexahedral. The
   * node data "target_position" and the element data "image_mass_ratio" of
   * a rest_shape.msh (write_gmsh()) become the description's targets and
   * mass ratios; a file with only part of them is refused.
   */
  MeshDescription
  read_gmsh(const std::string &file, const double length_unit);

  /**
   * What every mesh reader ends with: at least one cell, one cell type
   * (InputError naming @p file and @p parameter otherwise), and the
   * vertices no cell uses dropped (names kept).
   */
  MeshDescription
  finish_read_mesh(MeshDescription    mesh,
                   const std::string &file,
                   const std::string &parameter);

  /**
   * The names of the volume labels of a gmsh file (its $PhysicalNames of
   * dimension 3), read without reading the mesh. Names that cannot name a
   * label in a scene (LabelNames::is_valid_name(), e.g. with blanks) are
   * left out. Empty for a file without names or that cannot be read.
   */
  LabelNames
  read_gmsh_label_names(const std::string &file);

  /// The edges of gmsh's 10-node tetrahedron: its nodes 4 to 9 join these
  /// pairs of its vertices (deal.II's vertex order is gmsh's).
  constexpr unsigned int gmsh_tet10_edges[6][2] =
    {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {2, 3}, {1, 3}};

  /// The names of a rest shape's data in a gmsh file: node data of the
  /// target and equilibrium positions, element data of the mass ratios.
  inline const std::string gmsh_target_view      = "target_position";
  inline const std::string gmsh_equilibrium_view = "equilibrium_position";
  inline const std::string gmsh_mass_ratio_view  = "image_mass_ratio";

  /// What a rest shape carries besides its geometry (MeshDescription).
  struct RestShapeData
  {
    /// The target position (m) of vertex v.
    std::function<dealii::Point<3>(unsigned int)> target;
    /// Per active cell, in order: its mass in the image over its density
    /// times its volume in the rest shape.
    std::vector<double> mass_ratios;
    /// A quadratic rest shape (tetrahedra only): per active cell, in
    /// order, the rest positions (m) of its six edge nodes in the order
    /// of gmsh_tet10_edges; empty: linear cells.
    std::vector<std::array<dealii::Point<3>, 6>> edge_nodes;
    /// Where the run that writes the file left vertex v (m), and per cell
    /// its edge nodes (as edge_nodes); unset: not written.
    std::function<dealii::Point<3>(unsigned int)> equilibrium;
    std::vector<std::array<dealii::Point<3>, 6>>  edge_equilibria;
  };

  /**
   * Write the active cells of @p tria as gmsh 2.2 ASCII with labels as
   * physical volume tags. Vertex v is written at position(v) divided by
   * @p length_unit. With @p rest (a rest shape), also the node data
   * "target_position" (length unit) and the element data
   * "image_mass_ratio". Labels with @p names get them as $PhysicalNames.
   * Written atomically.
   */
  void
  write_gmsh(const dealii::Triangulation<3>                      &tria,
             const std::function<dealii::Point<3>(unsigned int)> &position,
             const double                                         length_unit,
             const std::string                                   &file,
             const RestShapeData *rest  = nullptr,
             const LabelNames    &names = LabelNames());

  /// The same for the cells of @p mesh in its order.
  void
  write_gmsh(const MeshDescription                               &mesh,
             const std::function<dealii::Point<3>(unsigned int)> &position,
             const double                                         length_unit,
             const std::string                                   &file,
             const RestShapeData                                 *rest,
             const LabelNames                                    &names);

  /// A boundary triangle to write with the cells: its vertices (outward
  /// oriented) and its physical surface tag.
  struct SurfaceTriangle
  {
    std::array<unsigned int, 3> vertices;
    int                         tag;
  };

  /// The same for a mesh description (vertices in metres), with the
  /// triangles of @p surfaces as gmsh physical surfaces named by
  /// @p surface_names (tag -> name); RestShape's readers take the volumes
  /// alone, ParaView and meshio show both.
  void
  write_gmsh(const MeshDescription              &mesh,
             const double                        length_unit,
             const std::string                  &file,
             const std::vector<SurfaceTriangle> &surfaces      = {},
             const std::map<int, std::string>   &surface_names = {});

} // namespace RestShape

#endif
