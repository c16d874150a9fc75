// Newton's method with line search, inexact linear tolerances and the
// tangent strategy, inside load stepping, for a NewtonSystem; contact
// enters through ActiveSetConstraints. Implemented in newton_solver.cc
// (Newton's steps) and newton_load_stepping.cc (the load steps and their
// halvings).
#ifndef restshape_solver_newton_solver_h
#define restshape_solver_newton_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <restshape/base/tangent_type.h>
#include <restshape/solver/active_set_conditions.h>
#include <restshape/solver/active_set_constraints.h>
#include <restshape/solver/linear_solver.h>
#include <restshape/solver/newton_system.h>
#include <restshape/solver/newton_watchdog.h>
#include <restshape/solver/solver_parameters.h>
#include <restshape/solver/tangent_strategy.h>

#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace RestShape
{

  struct SolveStatistics
  {
    bool         converged          = false;
    unsigned int newton_iterations  = 0; // linear solves, all load steps
    unsigned int load_steps         = 0; // accepted increments
    unsigned int linear_iterations  = 0;
    unsigned int active_set_changes = 0;
    double       residual           = 0; // final, N
    double       reference          = 0; // norm of the external loads, N
    std::string  failure;                // why it did not converge
    /// The last failed Newton solve failed because its line search's
    /// trial steps inverted cells.
    bool cells_inverted = false;
    /// Fraction of the way from the start to the target load and rest shape
    /// at which the state is in equilibrium: 1 when converged, less when
    /// the load-step halvings ran out part of the way (0: not even the
    /// smallest increment converged).
    double fraction = 0;
    /// |R|/|f| after every accepted Newton step of the last load step
    /// since its constraints (the active contact set) last changed.
    std::vector<double> residual_history;
    /// The round-off level of |R|/|f| where it was measured (a stalled
    /// step; 0: not measured since the constraints last changed).
    double round_off = 0;
    /// |K delta - b| of the last Newton step's linear system (N; direct
    /// solver only): the floor of what that step could reach.
    double linear_residual = 0;
    /// Newton converged at that level, above the Newton tolerance (which
    /// was then not met).
    bool at_round_off = false;
  };

  /// The load increments of a load-stepped solve, as fractions of the
  /// way from the start to the target: an accepted increment doubles the
  /// next one (up to the rest of the way), a failed one is halved.
  struct LoadSteps
  {
    double done      = 0; // fraction in equilibrium
    double increment = 1;

    /// The fraction to try next.
    double
    next() const
    {
      return std::min(1., done + increment);
    }
    void
    accept(const double s)
    {
      done      = s;
      increment = std::min(2 * increment, 1.);
    }
    /// Half the increment that failed (which may have been cut at the full
    /// load: halving the nominal increment alone retried the same step).
    void
    reject(const double s)
    {
      increment = (s - done) / 2;
    }
  };

  class NewtonSolver
  {
  public:
    /// @p solver: the Solver subsection; @p tangent: Discretization/Tangent.
    NewtonSolver(NewtonSystem               &system,
                 const SolverParameters     &solver,
                 const TangentType           tangent,
                 dealii::TimerOutput        &timer,
                 dealii::ConditionalOStream &pcout);

    /// After the system's set-up: the layout of its unknowns, and the
    /// linear solver of the steps (owned by the caller) and its kind.
    void
    setup(LinearSolver *solver, const LinearSolverType kind);
    /// Optional contact (owned by the caller; nullptr: none).
    void
    set_contact(ActiveSetConstraints *contact);

    /// Newton for the system's current load: per step the convergence
    /// check, the linear step, the line search, the tangent for the next
    /// step (TangentStrategy). True if converged (@p stats says how).
    bool
    solve(SolveStatistics &stats);

    /**
     * Load stepping from the system's current equilibrium (fraction 0) to
     * fraction 1: @p set_fraction puts the load and rest shape of a
     * fraction into the system. Increments are halved when Newton fails;
     * the state is left at the last equilibrium reached.
     */
    SolveStatistics
    solve_load_steps(const std::function<void(double)> &set_fraction);

    /// The contact conditions checked at the end of the last solve with
    /// contact (ActiveSetConstraints::check_conditions()).
    const ContactConditions &
    contact_conditions() const
    {
      return last_conditions;
    }

  private:
    /// Newton's state at the top of a step.
    enum class State
    {
      converged,
      failed, // stats.failure says why
      iterate,
      /// Converged, but contact constraints were released (adhesive nodes,
      /// violated conditions): Newton goes on with the new constraints.
      released
    };
    /// Whether the state meets the tolerance (or has reached the round-off
    /// floor) and, with contact, the contact conditions; releases adhesive
    /// nodes and enforces the conditions (++@p corrections) on the way
    /// (then `released`).
    State
    convergence_check(SolveStatistics &stats,
                      const double     residual,
                      const double     reference,
                      const bool       set_changed,
                      unsigned int    &corrections);
    /// At a converged Newton state with contact: whether the contact
    /// conditions hold against the obstacle (last_conditions); if not,
    /// enforce them (false; Newton goes on, ++@p corrections) or, when that
    /// cannot change anything, fail (false, stats.failure set).
    /// @p reference: the external force norm of the solve.
    bool
    contact_conditions_hold(SolveStatistics &stats,
                            const double     reference,
                            unsigned int    &corrections);

    /// Solve the linear system of a Newton step into update (Inexact
    /// Newton: @p previous holds the last step's residual and linear
    /// tolerance); returns the linear iterations.
    unsigned int
    linear_step(const double               residual,
                const double               target,
                std::pair<double, double> &previous,
                SolveStatistics           &stats);
    /// The relative tolerance of the linear solve of a Newton step with
    /// residual norm @p residual (Solver/Inexact Newton), given the
    /// previous step's residual and tolerance (0 at the first step) and
    /// the residual norm @p target at which Newton stops.
    double
    linear_tolerance(const double residual,
                     const double previous_residual,
                     const double previous_eta,
                     const double target) const;

    /// What the line search of a Newton step found.
    struct LineSearchResult
    {
      double       alpha_max       = 1; // the longest step contact allows
      double       alpha           = 1; // the step taken (if accepted)
      double       trial_residual  = 0;
      bool         accepted        = false;
      unsigned int inverted_trials = 0;
      bool         let_through     = false; // on trial (NewtonWatchdog)
    };
    /// Backtrack along update (Armijo on the potential energy, or on the
    /// residual norm); the state is restored when no step is accepted.
    LineSearchResult
    line_search(const double    residual,
                const double    reference,
                const bool      set_changed,
                NewtonWatchdog *watchdog);
    /// Go back to the state a failed watchdog trial started from.
    void
    restore_checkpoint(const NewtonWatchdog &watchdog, SolveStatistics &stats);
    /// After a step the line search rejected: true if Newton retries
    /// from the same state with another tangent or shift (@p strategy),
    /// false if it fails (stats.failure says why).
    bool
    retry_rejected_step(TangentStrategy        &strategy,
                        const LineSearchResult &ls,
                        const double            residual,
                        const double            reference,
                        SolveStatistics        &stats);
    /// The progress line of Newton step @p it.
    void
    print_step(const unsigned int      it,
               const double            relative_residual,
               const double            reference,
               const LineSearchResult &ls,
               const unsigned int      linear_iterations,
               const double            shift) const;
    /// Why Newton stalls although its tangent's diagonal was shifted.
    std::string
    shift_failure(const double relative_residual, const bool inverted) const;

    /**
     * The round-off level of the residual at the current state (N): the
     * change of the residual when every free displacement moves by the
     * smallest amount the state resolves (an ulp of d, or eps h_min, where
     * F = I + grad d stops resolving it), less the tangent's linear response
     * to that move. What remains is the noise of evaluating the residual,
     * below which no Newton step can bring it. Needs the tangent of the
     * current state; one residual assembly; the assembled vectors are kept.
     */
    double
    measure_round_off();
    /// Scale the tangent's diagonal by (1 + @p mu) (Solver/Tangent shift).
    void
    shift_diagonal(const double mu);

    /// The failed Newton attempts of a load-stepped solve: how many, and
    /// those whose steps inverted cells (the smallest load fraction among
    /// them, and one of the cells).
    struct FailedAttempts
    {
      unsigned int count = 0, inverting = 0;
      double       inverting_fraction = 0;
      std::string  inverting_text;
      void
      add(const double fraction, const bool inverted, const std::string &text);
    };
    /// Why solve_load_steps() gives up: the physical cause where the
    /// attempts inverted cells, the last failure otherwise, the load
    /// fraction reached and the most compressed cell of its equilibrium.
    std::string
    give_up_text(const SolveStatistics &stats,
                 const FailedAttempts  &failed,
                 const unsigned int     halvings) const;

    NewtonSystem               &system;
    const SolverParameters     &parameters;
    const TangentType           configured_tangent;
    dealii::TimerOutput        &timer;
    dealii::ConditionalOStream &pcout;
    LinearSolver               *linear_solver      = nullptr;
    LinearSolverType            linear_solver_type = LinearSolverType::direct;
    ActiveSetConstraints       *contact            = nullptr;
    /// The constraints of the current step (the system's).
    const dealii::AffineConstraints<double> *constraints = nullptr;
    VectorType                               update; // the Newton step
    ContactConditions                        last_conditions;
  };
} // namespace RestShape

#endif
