// A vector field (the displacement d or the rest displacement w) on one
// cell: its local coefficients, gathered once per cell, and its values and
// gradients at the points of an FEValues or FEFaceValues of the scalar
// base element. This replaces FEValuesViews::get_function_values and
// _gradients on the vector element, which allocate a vector and look every
// coefficient up again on each call (a third of a P1 residual assembly,
// profile of prm/brain.prm), and the vector element's FEValues, which
// copies each scalar shape function three times.
#ifndef restshape_forward_local_field_h
#define restshape_forward_local_field_h

#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <vector>

namespace RestShape
{
  class LocalField
  {
  public:
    /// For the shape functions of @p fe: a system of 3 copies of one
    /// scalar element (FE_SimplexP or FE_Q).
    explicit LocalField(const dealii::FiniteElement<3> &fe);

    /// The coefficients of @p v at the cell's @p dofs.
    void
    gather(const dealii::LinearAlgebra::distributed::Vector<double> &v,
           const std::vector<dealii::types::global_dof_index>       &dofs);

    /// The field at each point of @p fe_values (of the base element).
    void
    values(const dealii::FEValuesBase<3>     &fe_values,
           std::vector<dealii::Tensor<1, 3>> &result) const;

    /// The gradient (result[q][c][k] = d field_c / dx_k) at each point.
    void
    gradients(const dealii::FEValuesBase<3>     &fe_values,
              std::vector<dealii::Tensor<2, 3>> &result) const;

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
    std::vector<unsigned int> component, scalar;
    std::vector<double>       coefficients;
  };
} // namespace RestShape

#endif
