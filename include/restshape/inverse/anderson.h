// Anderson acceleration of a fixed-point iteration x <- G(x).
#ifndef restshape_anderson_h
#define restshape_anderson_h

#include <restshape/solver/linear_solver.h>

#include <deque>

namespace RestShape
{
  /**
   * Anderson acceleration (type II, mixing 1) of x <- G(x) = x + f(x): with
   * the differences dX_i, dF_i of the last m iterates and residuals,
   *
   *   gamma = argmin |f_k - dF gamma|,   x_{k+1} = x_k + f_k - (dX + dF) gamma.
   *
   * Equivalent to the least-squares quasi-Newton IQN-ILS of Bols et al.
   * (2013). The least-squares problem is solved through its normal equations
   * with a small Tikhonov term; the oldest columns are dropped when the
   * Gram matrix is too ill-conditioned.
   */
  class AndersonAccelerator
  {
  public:
    explicit AndersonAccelerator(const unsigned int depth);

    /// Forget the history (after a rejected step).
    void
    reset();

    /**
     * The next iterate from the current iterate @p x and residual @p f =
     * G(x) - x. Without history: the plain update x + f.
     */
    VectorType
    next(const VectorType &x, const VectorType &f);

    /// Number of difference pairs used by the last next().
    unsigned int
    columns_used() const;

  private:
    const unsigned int     depth;
    std::deque<VectorType> dX, dF;
    VectorType             x_last, f_last;
    bool                   has_last = false;
    unsigned int           used     = 0;
  };
} // namespace RestShape

#endif
