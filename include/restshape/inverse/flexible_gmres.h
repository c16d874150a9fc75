// Flexible GMRES that stops at the product that meets its tolerance.
#ifndef restshape_flexible_gmres_h
#define restshape_flexible_gmres_h

#include <restshape/forward/forward_problem.h>

#include <functional>

namespace RestShape
{
  /// What one FlexibleGmres::solve() did.
  struct FlexibleGmresResult
  {
    unsigned int iterations = 0; // operator products (and preconditioner)
    double       residual   = 0; // |b - A x|, GMRES's estimate
  };

  /**
   * Right-preconditioned flexible GMRES (Saad's FGMRES, no restart) for
   * A x = b from x = 0: the preconditioner may change from one
   * application to the next (an inexact inner solve). Each iteration
   * applies the preconditioner and the operator once and updates the
   * residual estimate by Givens rotations, so the solve stops at the
   * iteration that reaches the tolerance. (deal.II 9.4's SolverFGMRES
   * estimates the residual one basis vector late: every solve costs one
   * product more than it uses, which in the direct inverse is a residual
   * assembly plus an inner solve.)
   */
  class FlexibleGmres
  {
  public:
    using Operator = std::function<void(VectorType &, const VectorType &)>;

    /// At most @p max_iterations iterations.
    explicit FlexibleGmres(const unsigned int max_iterations);

    /// x for A x = b, stopping once |b - A x| <= @p tolerance (absolute)
    /// or after max_iterations (the best x in the space built so far).
    FlexibleGmresResult
    solve(const Operator   &A,
          const Operator   &preconditioner,
          VectorType       &x,
          const VectorType &b,
          const double      tolerance) const;

  private:
    unsigned int max_iterations;
  };
} // namespace RestShape

#endif
