// The values, gradients, normals and area weights of a scalar element at
// the quadrature points of one face of an affine tetrahedron, from the
// cell's four vertices, as FEFaceValues with MappingFE of FE_SimplexP(1)
// computes them: the face rule projected onto the reference face of each
// orientation (QProjector), the cell's Jacobian J, the boundary form
// (J t_0) x (J t_1) of the reference face's tangentials, JxW = its norm
// times the weight. FEFaceValues' general machinery (support points
// through the manifold, per-point Jacobians and virtual transforms) took
// 60 % of the face terms' set-up (profile of the P1 brain assembly).
#ifndef restshape_fem_simplex_face_values_h
#define restshape_fem_simplex_face_values_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/tria.h>

#include <restshape/fem/simplex_values.h>

#include <array>
#include <vector>

namespace RestShape
{
  class SimplexFaceValues
  {
  public:
    /// For the scalar simplex element @p fe at the points of the face rule
    /// @p quadrature.
    SimplexFaceValues(const dealii::FiniteElement<3> &fe,
                      const dealii::Quadrature<2>    &quadrature);

    /// On face @p face of the tetrahedron @p cell (straight edges).
    void
    reinit(const dealii::Triangulation<3>::cell_iterator &cell,
           const unsigned int                             face);

    double
    shape_value(const unsigned int k, const unsigned int q) const
    {
      return current->shape_value(k, q);
    }
    const dealii::Tensor<1, 3> &
    shape_grad(const unsigned int k, const unsigned int q) const
    {
      return current->shape_grad(k, q);
    }
    double
    JxW(const unsigned int q) const
    {
      return JxW_values[q];
    }
    const dealii::Tensor<1, 3> &
    normal_vector(const unsigned int q) const
    {
      return normals[q];
    }
    const dealii::Point<3> &
    quadrature_point(const unsigned int q) const
    {
      return current->quadrature_point(q);
    }

    const unsigned int n_quadrature_points;
    const unsigned int dofs_per_cell;

  private:
    static constexpr unsigned int n_faces = 4;

    /// The cell values at the projected points, one per data set of
    /// QProjector (a face in one orientation), and their weights.
    std::vector<SimplexValues>                               sets;
    std::vector<std::vector<double>>                         weights;
    std::array<std::array<dealii::Tensor<1, 3>, 2>, n_faces> tangentials;

    SimplexValues                    *current = nullptr;
    std::vector<double>               JxW_values;
    std::vector<dealii::Tensor<1, 3>> normals;
  };
} // namespace RestShape

#endif
