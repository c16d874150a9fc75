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

} // namespace RestShape
