// The parameters of subsection Verification.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/postprocess/verification_parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  VerificationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    prm.declare_entry("Exact displacement",
                      "",
                      Patterns::Anything(),
                      "Optional exact displacement for verification: three "
                      "muparser expressions 'ux; uy; uz' in the mesh's "
                      "length unit, functions of the reference coordinates "
                      "x, y, z (same unit). When given, the L2 and H1 errors "
                      "are computed and written to convergence.csv.");
    prm.declare_entry("Exact rest displacement",
                      "",
                      Patterns::Anything(),
                      "Optional, for the inverse problem: the exact X_rest - "
                      "X_target as three muparser expressions of x, y, z "
                      "(mesh length unit). When given, the errors of the "
                      "computed rest shape are written to convergence.csv.");
    prm.leave_subsection();
  }

  void
  VerificationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    exact_displacement = dealii::Utilities::trim(prm.get("Exact displacement"));
    exact_rest_displacement =
      dealii::Utilities::trim(prm.get("Exact rest displacement"));
    prm.leave_subsection();
  }
} // namespace RestShape
