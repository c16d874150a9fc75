// A vector field (the displacement d or the rest displacement w) on one
// cell: its local coefficients, gathered once per cell, and its values and
// gradients at the points of an FEValues, FEFaceValues or SimplexValues of the
// scalar base element. This replaces FEValuesViews::get_function_values and
// _gradients on the vector element, which allocate a vector and look every
// coefficient up again on each call (a third of a P1 residual assembly,
// profile of prm/brain.prm), and the vector element's FEValues, which
// copies each scalar shape function three times.
#ifndef restshape_fem_local_field_h
#define restshape_fem_local_field_h

#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <algorithm>
#include <vector>

namespace RestShape
{
  class LocalField
  {
  public:
    /// For the shape functions of @p fe: a system of 3 copies of one
    /// scalar element (FE_SimplexP or FE_Q).
    explicit LocalField(const dealii::FiniteElement<3> &fe);

    /// The coefficients of @p v at the cell's DoFs of local indices
    /// @p local (CellLocalIndices).
    void
    gather_local(const dealii::LinearAlgebra::distributed::Vector<double> &v,
                 const std::vector<unsigned int> &local);

    /// The field at each point of @p values (of the base element: an
    /// FEValues, FEFaceValues or SimplexValues).
    template <typename Values>
    void
    values(const Values                      &values,
           std::vector<dealii::Tensor<1, 3>> &result) const
    {
      accumulate(values,
                 result,
                 [&](const unsigned int k, const unsigned int q) {
                   return values.shape_value(k, q);
                 });
    }

    /// The gradient (result[q][c][k] = d field_c / dx_k) at each point.
    template <typename Values>
    void
    gradients(const Values                      &values,
              std::vector<dealii::Tensor<2, 3>> &result) const
    {
      accumulate(values,
                 result,
                 [&](const unsigned int k, const unsigned int q) {
                   return values.shape_grad(k, q);
                 });
    }

    /// The coefficients, in the cell's local DoF order.
    const double *
    data() const
    {
      return coefficients.data();
    }

    /// The coefficient of shape function @p i.
    double
    operator[](const unsigned int i) const
    {
      return coefficients[i];
    }

    /// The vector component of each shape function.
    const std::vector<unsigned int> &
    components() const
    {
      return component;
    }

    /// The base element's shape function of each shape function.
    const std::vector<unsigned int> &
    scalar_functions() const
    {
      return scalar;
    }

  private:
    /// result[q][c] = sum_i coefficient_i shape(scalar_i, q), c the
    /// component of shape function i: in the order of the shape functions,
    /// skipping zero coefficients, as deal.II's get_function_values and
    /// _gradients do, of the same scalar values: the same numbers.
    template <typename Values, typename Result, typename Shape>
    void
    accumulate(const Values        &values,
               std::vector<Result> &result,
               const Shape         &shape) const
    {
      const unsigned int n_points = values.n_quadrature_points;
      std::fill(result.begin(), result.begin() + n_points, Result());
      for (unsigned int i = 0; i < component.size(); ++i)
        if (const double value = coefficients[i]; value != 0)
          for (unsigned int q = 0; q < n_points; ++q)
            result[q][component[i]] += value * shape(scalar[i], q);
    }

    std::vector<unsigned int> component, scalar;
    std::vector<double>       coefficients;
  };
} // namespace RestShape

#endif
