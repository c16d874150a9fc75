// Errors of the computed displacement against an exact one given in the
// .prm file (manufactured or analytic solutions).
#ifndef restshape_verification_h
#define restshape_verification_h

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>

#include <restshape/forward/forward_problem.h>

#include <memory>
#include <string>

namespace RestShape
{
  struct DisplacementErrors
  {
    double l2_relative = 0; // |u - u_ex|_L2 / |u_ex|_L2
    double h1_relative =
      0; // |grad(u - u_ex)|_L2 / |grad u_ex|_L2 (absolute if grad u_ex = 0)
    double max_nodal_error = 0; // max over nodes of |u - u_ex| (m)
  };

  class ExactDisplacement
  {
  public:
    /**
     * @p expressions: "ux; uy; uz" (muparser) in the unit @p length_unit
     * (metres per unit) as functions of x, y, z in the same unit. Throws
     * InputError naming Verification/Exact displacement.
     */
    ExactDisplacement(
      const std::string &expressions,
      const double       length_unit,
      const std::string &parameter = "Verification/Exact displacement");

    /// Errors of the field @p u (owned or ghosted, in the DoF layout of
    /// @p problem), e.g. the displacement d - w or the rest displacement w.
    DisplacementErrors
    errors(const ForwardProblem &problem, const VectorType &u) const;

    /// Throws InputError naming the parameter if the expressions give a
    /// value that is not a finite number (sqrt(-1), 1/0, log(0)) at a
    /// vertex or a cell centre of @p tria (collective on its communicator).
    void
    check_finite_on(const dealii::Triangulation<3> &tria) const;

  private:
    std::string parameter;
    class SIFunction;
    std::unique_ptr<dealii::Function<3>> function;
  };
} // namespace RestShape

#endif
