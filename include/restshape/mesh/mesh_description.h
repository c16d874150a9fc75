// A mesh before it becomes a Triangulation: vertices (m) and labelled cells.
#ifndef restshape_mesh_mesh_description_h
#define restshape_mesh_mesh_description_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <restshape/base/label_names.h>
#include <restshape/mesh/rest_shape_nodes.h>

#include <vector>

namespace RestShape
{
  /**
   * Vertices (in metres) and cells with labels, before a Triangulation.
   * A rest shape written by an inverse run (rest_shape.msh) also carries,
   * per vertex, the target position (m) it reaches at equilibrium and, per
   * cell, the ratio of its mass in the image to its density times its
   * volume here (mass is conserved: the rest shape only redistributes it);
   * both are empty for other meshes.
   */
  struct MeshDescription
  {
    std::vector<dealii::Point<3>>    vertices;
    std::vector<dealii::CellData<3>> cells;
    std::vector<dealii::Point<3>>    targets;
    std::vector<double>              mass_ratios;
    /// A rest_shape.msh's edge nodes and equilibria (by position).
    RestShapeNodes rest_nodes;
    /// Names of labels (gmsh $PhysicalNames), may be empty.
    LabelNames names;

    /// Add a vertex at the centroid of the vertices @p of (and its target
    /// at the centroid of theirs); returns its index.
    unsigned int
    add_centroid(const std::vector<unsigned int> &of)
    {
      const auto mean = [&](const std::vector<dealii::Point<3>> &points) {
        dealii::Point<3> c;
        for (const unsigned int i : of)
          c += points[i];
        return dealii::Point<3>(c / static_cast<double>(of.size()));
      };
      if (!targets.empty())
        targets.push_back(mean(targets));
      vertices.push_back(mean(vertices));
      return vertices.size() - 1;
    }
    /// Add cell @p cell, a part of cell @p parent of @p from (its mass
    /// ratio inherited).
    void
    add_part(const dealii::CellData<3> &cell,
             const MeshDescription     &from,
             const unsigned int         parent)
    {
      cells.push_back(cell);
      if (!from.mass_ratios.empty())
        mass_ratios.push_back(from.mass_ratios[parent]);
    }
  };

  /// The triple product (a x b) . c: six times a tetrahedron's signed volume.
  inline double
  triple_product(const dealii::Tensor<1, 3> &a,
                 const dealii::Tensor<1, 3> &b,
                 const dealii::Tensor<1, 3> &c)
  {
    return dealii::cross_product_3d(a, b) * c;
  }
} // namespace RestShape

#endif
