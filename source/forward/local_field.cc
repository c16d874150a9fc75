#include <restshape/forward/local_field.h>

#include <tuple>

namespace RestShape
{
  using namespace dealii;

  LocalField::LocalField(const FiniteElement<3> &fe)
    : component(fe.n_dofs_per_cell())
    , scalar(fe.n_dofs_per_cell())
    , coefficients(fe.n_dofs_per_cell())
  {
    AssertThrow(fe.n_base_elements() == 1 && fe.n_components() == 3,
                ExcMessage("expected 3 copies of one scalar element"));
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      std::tie(component[i], scalar[i]) = fe.system_to_component_index(i);
  }

  void
  LocalField::gather(const LinearAlgebra::distributed::Vector<double> &v,
                     const std::vector<types::global_dof_index>       &dofs)
  {
    for (unsigned int i = 0; i < dofs.size(); ++i)
      coefficients[i] = v(dofs[i]);
  }

  // Sums in the order of the shape functions, skipping zero coefficients,
  // as deal.II's get_function_values/gradients do, of the same scalar
  // values: the same numbers.
  void
  LocalField::values(const FEValuesBase<3>     &fe_values,
                     std::vector<Tensor<1, 3>> &result) const
  {
    const unsigned int n_points = fe_values.n_quadrature_points;
    std::fill(result.begin(), result.begin() + n_points, Tensor<1, 3>());
    for (unsigned int i = 0; i < coefficients.size(); ++i)
      {
        const double value = coefficients[i];
        if (value == 0)
          continue;
        const unsigned int c = component[i];
        for (unsigned int q = 0; q < n_points; ++q)
          result[q][c] += value * fe_values.shape_value(scalar[i], q);
      }
  }

  void
  LocalField::gradients(const FEValuesBase<3>     &fe_values,
                        std::vector<Tensor<2, 3>> &result) const
  {
    const unsigned int n_points = fe_values.n_quadrature_points;
    std::fill(result.begin(), result.begin() + n_points, Tensor<2, 3>());
    for (unsigned int i = 0; i < coefficients.size(); ++i)
      {
        const double value = coefficients[i];
        if (value == 0)
          continue;
        const unsigned int c = component[i];
        for (unsigned int q = 0; q < n_points; ++q)
          result[q][c] += value * fe_values.shape_grad(scalar[i], q);
      }
  }
} // namespace RestShape
