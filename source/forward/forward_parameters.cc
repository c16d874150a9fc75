#include <restshape/forward/forward_parameters.h>

namespace RestShape
{
  void
  ForwardParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    DiscretizationParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    BoundaryParameters::declare_parameters(prm);
    LoadParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
  }

  void
  ForwardParameters::parse_parameters(dealii::ParameterHandler &prm,
                                      const double              length_unit)
  {
    discretization.parse_parameters(prm);
    materials.parse_parameters(prm);
    boundary.parse_parameters(prm);
    loads.parse_parameters(prm);
    solver.parse_parameters(prm);
    loads.fluid_level *= length_unit;
  }
} // namespace RestShape
