#include <restshape/forward/forward_parameters.h>

namespace RestShape
{
  void
  ForwardParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    DiscretizationParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
  }

  void
  ForwardParameters::parse_parameters(dealii::ParameterHandler &prm,
                                      const double              length_unit)
  {
    discretization.parse_parameters(prm);
    materials.parse_parameters(prm);
    environment.parse_parameters(prm, length_unit);
    solver.parse_parameters(prm);
  }
} // namespace RestShape
