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

  namespace
  {
    // result[q][c] = sum_i coefficient_i shape(scalar_i, q), c the
    // component of shape function i: in the order of the shape functions,
    // skipping zero coefficients, as deal.II's get_function_values and
    // _gradients do, of the same scalar values: the same numbers.
    template <typename Result, typename Shape>
    void
    accumulate(const LocalField      &field,
               const FEValuesBase<3> &fe_values,
               std::vector<Result>   &result,
               const Shape           &shape)
    {
      const std::vector<unsigned int> &component = field.components();
      const std::vector<unsigned int> &scalar    = field.scalar_functions();
      const unsigned int               n_points = fe_values.n_quadrature_points;
      std::fill(result.begin(), result.begin() + n_points, Result());
      for (unsigned int i = 0; i < component.size(); ++i)
        if (const double value = field[i]; value != 0)
          for (unsigned int q = 0; q < n_points; ++q)
            result[q][component[i]] += value * shape(scalar[i], q);
    }
  } // namespace

  void
  LocalField::values(const FEValuesBase<3>     &fe_values,
                     std::vector<Tensor<1, 3>> &result) const
  {
    accumulate(*this,
               fe_values,
               result,
               [&](const unsigned int k, const unsigned int q) {
                 return fe_values.shape_value(k, q);
               });
  }

  void
  LocalField::gradients(const FEValuesBase<3>     &fe_values,
                        std::vector<Tensor<2, 3>> &result) const
  {
    accumulate(*this,
               fe_values,
               result,
               [&](const unsigned int k, const unsigned int q) {
                 return fe_values.shape_grad(k, q);
               });
  }
} // namespace RestShape
