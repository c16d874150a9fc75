// The values, gradients and volume weights of a scalar element at the
// quadrature points of one affine tetrahedron, computed from its four
// vertices and the reference cell's data, as FEValues with MappingFE of
// FE_SimplexP(1) computes them (the same Jacobian, covariant form and
// products), without that class's general machinery: the mapping's
// support points through the manifold, the per-point Jacobians, the
// transformation of each gradient through virtual calls (14,000
// instructions per P2 cell, 18 % of a residual assembly).
#ifndef restshape_fem_simplex_values_h
#define restshape_fem_simplex_values_h

#include <deal.II/base/derivative_form.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace RestShape
{
  class SimplexValues
  {
  public:
    /// For the scalar simplex element @p fe at the points of @p quadrature.
    SimplexValues(const dealii::FiniteElement<3> &fe,
                  const dealii::Quadrature<3>    &quadrature);

    /// The points @p start to @p start + @p n of @p all as a rule of
    /// their own (built without the reference cell's FEValues).
    SimplexValues(const SimplexValues &all,
                  const unsigned int   start,
                  const unsigned int   n);

    /// On the tetrahedron @p cell (straight edges).
    void
    reinit(const dealii::Triangulation<3>::cell_iterator &cell);

    double
    shape_value(const unsigned int k, const unsigned int q) const
    {
      return values[k * n_quadrature_points + q];
    }
    const dealii::Tensor<1, 3> &
    shape_grad(const unsigned int k, const unsigned int q) const
    {
      return gradients[k * n_quadrature_points + q];
    }
    double
    JxW(const unsigned int q) const
    {
      return JxW_values[q];
    }
    const dealii::Point<3> &
    quadrature_point(const unsigned int q) const
    {
      return points[q];
    }
    /// The mean of the vertices, as cell->center() computes it.
    const dealii::Point<3> &
    center() const
    {
      return vertex_mean;
    }
    /// The Jacobian of the map from the reference cell (constant).
    const dealii::DerivativeForm<1, 3, 3> &
    jacobian() const
    {
      return J;
    }

    const unsigned int n_quadrature_points;
    const unsigned int dofs_per_cell;

  private:
    std::vector<double>               weights;
    std::vector<double>               values;              // [k][q]
    std::vector<dealii::Tensor<1, 3>> reference_gradients; // [k][q]
    std::vector<double>               vertex_shapes;       // [q][vertex]
    std::vector<dealii::Tensor<1, 3>> gradients;           // [k][q]
    std::vector<double>               JxW_values;
    std::vector<dealii::Point<3>>     points;
    dealii::DerivativeForm<1, 3, 3>   J;
    dealii::Point<3>                  vertex_mean;
  };
} // namespace RestShape

#endif
