// ForwardProblem: the load terms (load_set.h) on its discretisation.
#include <restshape/forward/forward_problem.h>

namespace RestShape
{
  using namespace dealii;

  void
  ForwardProblem::setup_load_terms()
  {
    const LoadContext context{discretization_.mesh(),
                              material_table,
                              discretization_.mapping(),
                              discretization_.fe(),
                              discretization_.face_quadrature(),
                              discretization_.dof_handler(),
                              discretization_.communicator(),
                              [this](const types::global_dof_index dof) {
                                return discretization_.is_held(dof);
                              },
                              [this](const Label label) {
                                return parameters.discretization.fully_fixed(
                                  label);
                              },
                              parameters.set_later};
    load_set.create(parameters.load_terms, context);
  }
} // namespace RestShape
