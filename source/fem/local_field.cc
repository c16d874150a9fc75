#include <restshape/fem/local_field.h>

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
  LocalField::gather_local(const LinearAlgebra::distributed::Vector<double> &v,
                           const std::vector<unsigned int> &local)
  {
    for (unsigned int i = 0; i < local.size(); ++i)
      coefficients[i] = v.local_element(local[i]);
  }

} // namespace RestShape
