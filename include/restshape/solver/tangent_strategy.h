// Which tangent Newton's next step uses (Discretization/Tangent) and how
// far its diagonal is shifted (Solver/Tangent shift), from what the line
// search of each step found.
#ifndef restshape_solver_tangent_strategy_h
#define restshape_solver_tangent_strategy_h

#include <restshape/base/tangent_type.h>

namespace RestShape
{
  /**
   * For a fixed tangent (consistent, projected, warped) nothing changes.
   * For `adaptive`: the consistent tangent, but after a step the line
   * search had to shorten, one step with the projected one; when no step
   * along the consistent direction helps, the projected one from the same
   * state. With a tangent shift s > 0 (adaptive only) instead of the
   * projected steps a Levenberg-Marquardt shift mu of the diagonal: s after
   * the first shortened step, 10 mu after each further one (or when no step
   * helps), mu / 10 after each full step and 0 once below s / 1000.
   */
  class TangentStrategy
  {
  public:
    /// Beyond this shift a step is below 1e-4 of a Jacobi step: raising it
    /// further cannot help (measured: P2 at gravity x 10 raised it to 1e95
    /// in 90 useless steps per load increment; increments that converged
    /// never needed more than 1). Then the Newton solve fails and the load
    /// increment is halved.
    static constexpr double max_shift = 1e4;

    TangentStrategy(const TangentType chosen, const double tangent_shift);

    /// The tangent of the next step (never `adaptive`).
    TangentType
    tangent() const;

    /// The relative diagonal shift of the next step (0: none).
    double
    shift() const;

    /// After a step the line search accepted, @p shortened if below its
    /// largest length. false: the shift would exceed max_shift.
    bool
    accepted(const bool shortened);

    /// What to do when the line search accepted no step.
    enum class Retry
    {
      /// Nothing to change: Newton fails.
      none,
      /// The projected tangent, from the same state.
      projected,
      /// A larger shift, from the same state.
      larger_shift,
      /// The shift would exceed max_shift: Newton fails.
      shift_exhausted
    };
    Retry
    rejected();

  private:
    /// mu = s, or 10 mu; false beyond max_shift.
    bool
    raise();

    const TangentType chosen;
    const double      shift_start;
    TangentType       current;
    double            mu = 0;
  };
} // namespace RestShape

#endif
