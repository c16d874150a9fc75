// Subsection "Inverse problem": the method and its stopping rules.
#ifndef restshape_inverse_inverse_parameters_h
#define restshape_inverse_inverse_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace RestShape
{
  struct InverseParameters
  {
    enum class Measure
    {
      mean,
      max
    };
    enum class Acceleration
    {
      none,
      anderson
    };
    bool         enabled;
    Measure      measure;
    double       tolerance;     // m, on the error measure
    double       max_tolerance; // m, on the largest nodal error
    unsigned int max_iterations;
    Acceleration acceleration;
    unsigned int anderson_depth;
    /// fixed point: the iteration from the target; direct: first Newton on
    /// the equilibrium at the target with the rest shape as unknown, then
    /// the fixed point from its rest shape (which checks and polishes it).
    enum class Method
    {
      fixed_point,
      direct
    } method = Method::fixed_point;
    /// The share of the reference contact forces the obstacle carries at
    /// the target (0: the least-force rest shape).
    double skull_load_share = 0;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
