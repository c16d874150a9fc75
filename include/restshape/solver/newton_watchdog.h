// NewtonWatchdog: full Newton steps taken on trial where the line search
// would shorten them (Chamberlain, Powell, Lemarechal and Pedersen 1982).
#ifndef restshape_solver_newton_watchdog_h
#define restshape_solver_newton_watchdog_h

#include <restshape/solver/linear_solver.h>

namespace RestShape
{
  /**
   * A monotone line search shortens a Newton step whenever the energy at
   * the full step lies above the Armijo line, even where the full step
   * leads to the solution in a few more steps: a beam bending under its
   * own weight from the straight state, whose first full step stretches it
   * (the linear prediction) and whose next steps turn the stretch into the
   * rotation. The watchdog takes such a step anyway, keeps the state it
   * started from, and gives the following steps (with their own line
   * searches) up to a number of steps to bring the energy below the Armijo
   * target of the step it let through. If they do not, Newton goes back to
   * the kept state and takes the line search's step from there; it lets
   * no further step through until a step has been accepted there, and at
   * most max_trials steps in one Newton solve (a tangent that is not exact,
   * whose full steps overshoot again and again, would otherwise pay the
   * trials over and over; NewtonSolver lets steps through only along the
   * consistent tangent, unshifted, and without contact).
   */
  class NewtonWatchdog
  {
  public:
    /// Full steps let through in one Newton solve, at most.
    static constexpr unsigned int max_trials = 2;

    /// @p steps: the steps a trial has to reach its target (0: off).
    explicit NewtonWatchdog(const unsigned int steps);

    /// Whether a full step the line search rejects may be taken on trial.
    bool
    may_let_through() const;
    /// A full step is taken on trial from @p start, whose energy (J) plus
    /// Armijo's fraction of the step's slope is @p target_energy.
    void
    let_through(const VectorType &start, const double target_energy);

    enum class Verdict
    {
      none,    // no trial, or a trial that still has steps left
      cleared, // the trial reached its target: the kept state is dropped
      restore  // the trial failed: go back to checkpoint()
    };
    /// After an accepted step whose end has @p energy (J).
    Verdict
    judge(const double energy);
    /// The trial must end now (its line search failed): whether there is a
    /// kept state to go back to.
    bool
    abandon();

    /// The state a failed trial goes back to.
    const VectorType &
    checkpoint() const;
    /// Steps the trial took.
    unsigned int
    trial_steps() const;
    /// Whether a step let through is on trial (not yet judged).
    bool
    on_trial() const
    {
      return active;
    }

  private:
    const unsigned int steps;
    bool               active  = false;
    bool               blocked = false;
    unsigned int       taken   = 0;
    unsigned int       trials  = 0; // let through in this solve
    double             target  = 0;
    VectorType         kept_state;
  };
} // namespace RestShape

#endif
