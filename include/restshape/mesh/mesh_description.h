// A mesh before it becomes a Triangulation: vertices (m) and labelled cells.
#ifndef restshape_mesh_mesh_description_h
#define restshape_mesh_mesh_description_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace RestShape
{
  /// Vertices (in metres) and cells with labels, before a Triangulation.
  struct MeshDescription
  {
    std::vector<dealii::Point<3>>    vertices;
    std::vector<dealii::CellData<3>> cells;
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
