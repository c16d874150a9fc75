// Subsection "Adaptive refinement": cycles, strategy and estimator.
#ifndef restshape_postprocess_refinement_parameters_h
#define restshape_postprocess_refinement_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace RestShape
{
  struct RefinementParameters
  {
    enum class Strategy
    {
      global,
      adaptive
    };
    enum class Estimator
    {
      kelly,
      traction_jump
    };
    unsigned int cycles;
    Strategy     strategy;
    Estimator    estimator         = Estimator::kelly;
    double       refine_fraction   = 0.3;  // of the cells, largest indicators
    double       coarsen_fraction  = 0.0;  // of the cells, smallest indicators
    bool         transfer_solution = true; // start from the previous cycle

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
