// The parameters of subsection Discretization.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/fem/discretization_parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  DiscretizationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    prm.declare_entry("Polynomial degree",
                      "1",
                      Patterns::Integer(1, 2),
                      "Degree of the Lagrange elements: 1 (P1 tetrahedra or "
                      "Q1 hexahedra) or 2 (P2 / Q2).");
    prm.declare_entry(
      "Tangent",
      "consistent",
      Patterns::Selection("consistent|projected|adaptive|warped"),
      "Newton tangent of the material law (Materials/Material law). "
      "consistent: the exact derivative (for the co-rotational law "
      "including the derivative of the rotation; quadratic convergence). "
      "projected: the exact derivative with its negative eigenvalues (the "
      "rotational modes of compressed points) set to zero, "
      "so the stiffness stays positive semi-definite "
      "(projected Newton; equal to consistent wherever that "
      "is positive; converges linearly where it differs). "
      "adaptive: consistent, but after a Newton step whose "
      "line search had to shorten the step, one step with "
      "the projected tangent. warped: co-rotational law only, R K0 R^T as "
      "in SOFA and Mueller et al. 2002 (no dR term; linear convergence), "
      "kept for comparison; other laws use their exact tangent.");
    prm.leave_subsection();
  }

  void
  DiscretizationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    degree       = prm.get_integer("Polynomial degree");
    tangent_name = prm.get("Tangent");
    tangent      = tangent_name == "warped"    ? TangentType::warped :
                   tangent_name == "projected" ? TangentType::projected :
                   tangent_name == "adaptive"  ? TangentType::adaptive :
                                                 TangentType::consistent;
    prm.leave_subsection();
  }
} // namespace RestShape
