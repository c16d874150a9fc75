// Subsection "Discretization": the element degree and the tangent.
#ifndef restshape_fem_discretization_parameters_h
#define restshape_fem_discretization_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace RestShape
{
  enum class TangentType
  {
    consistent,
    projected,
    adaptive,
    warped
  };

  struct DiscretizationParameters
  {
    unsigned int degree;
    TangentType  tangent;
    std::string  tangent_name; // as in the .prm, for summary.json

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
