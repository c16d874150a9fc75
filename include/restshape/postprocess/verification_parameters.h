// Subsection "Verification": exact solutions to compare with.
#ifndef restshape_postprocess_verification_parameters_h
#define restshape_postprocess_verification_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace RestShape
{
  struct VerificationParameters
  {
    std::string exact_displacement;      // muparser, 3 components; empty: none
    std::string exact_rest_displacement; // the same for X_rest - X

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
