// NewtonSolver: Newton's method with line search (and inexact linear
// tolerances) for a NewtonSystem, with an optional active set (contact).

#include <restshape/base/format_text.h>
#include <restshape/base/progress.h>
#include <restshape/solver/newton_progress.h>
#include <restshape/solver/newton_solver.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// A stalled residual within this factor of the measured round-off
    /// level is at that level (seen: a plateau at 2.5e-10 against a
    /// measured 2.8e-10, P1 cantilever refined twice).
    constexpr double round_off_margin = 3;
    /// Step lengths tried by the line search: 1, 1/2, ..., 1/2^11.
    constexpr unsigned int line_search_trials = 12;
    /// Armijo's sufficient decrease.
    constexpr double armijo = 1e-4;
    /// Below this |R|/|f| (and above the tolerance), while releases are
    /// frozen, the active nodes that pull are released at the top of a
    /// Newton step (at most five times a solve): waiting for the tolerance
    /// cost 1-3 steps per release round that the release then throws away
    /// (doc/contact.md). With the active nodes on the obstacle's faces,
    /// the 16 P1 cases of doc/changes/contact-steps.md took 220 Newton
    /// steps with 1e-2, 200 with 1e-1 and 196 with 1 (the 6 P2 cases 103
    /// with 1e-1, 96 with 1). A node released too early comes back only
    /// through the obstacle, and the strict check of the converged state
    /// judges in any case.
    constexpr double release_check_residual = 1;

    /// A change of the constraints or of the state (a release, a new
    /// active set, a return to the watchdog's kept state) starts a new
    /// convergence history.
    void
    start_new_history(SolveStatistics &stats)
    {
      stats.residual_history.clear();
      stats.round_off = 0;
    }
  } // namespace

  NewtonSolver::NewtonSolver(NewtonSystem           &system,
                             const SolverParameters &solver,
                             const TangentType       tangent,
                             TimerOutput            &timer,
                             ConditionalOStream     &pcout)
    : system(system)
    , parameters(solver)
    , configured_tangent(tangent)
    , timer(timer)
    , pcout(pcout)
  {}

  void
  NewtonSolver::setup(LinearSolver *solver, const LinearSolverType kind)
  {
    linear_solver      = solver;
    linear_solver_type = kind;
    update.reinit(system.unknowns());
  }

  void
  NewtonSolver::set_contact(ActiveSetConstraints *c)
  {
    contact = c;
  }

  double
  NewtonSolver::linear_tolerance(const double residual,
                                 const double previous_residual,
                                 const double previous_eta,
                                 const double target) const
  {
    const double fixed = parameters.linear_tolerance;
    if (!parameters.inexact_newton)
      return fixed;
    // Eisenstat and Walker (1996), choice 2 with its safeguard.
    double eta = 0.1;
    if (previous_residual > 0)
      {
        const double ratio = residual / previous_residual;
        eta                = 0.9 * ratio * ratio;
        if (0.9 * previous_eta * previous_eta > 0.1)
          eta = std::max(eta, 0.9 * previous_eta * previous_eta);
        eta = std::min(eta, 0.1);
      }
    // Not tighter than the fixed tolerance; and where the Newton tolerance
    // is near, only as tight as reaching it needs.
    return std::max({eta, fixed, std::min(0.1, 0.5 * target / residual)});
  }

  double
  NewtonSolver::measure_round_off()
  {
    // The residual at displacements moved by about the smallest change the
    // state resolves (an ulp of d, or of F = I + grad d: eps h_min) at every
    // free DoF, less the tangent's linear response to that move: what is
    // left is the noise of evaluating the residual (at small strains, of
    // the co-rotational stress 2 mu (F - R): eps against the strain), the
    // level below which no Newton step can bring it. Needs the tangent of
    // the current state (the top of a Newton step).
    VectorType                   &d          = system.unknowns();
    const VectorType              d_start    = d;
    const NewtonSystem::Assembled before     = system.assembled();
    const double                  resolution = system.resolution();
    const dealii::IndexSet        owned      = d.locally_owned_elements();
    VectorType                    move(d);
    move = 0;
    for (const auto i : owned)
      if (!constraints->is_constrained(i))
        {
          const double sign =
            std::sin(12.9898 * double(i) + 78.233) >= 0 ? 1 : -1;
          const double ulp =
            std::abs(std::nextafter(d_start[i],
                                    std::numeric_limits<double>::infinity()) -
                     d_start[i]);
          move[i] = sign * std::max(ulp, resolution);
        }
    move.compress(VectorOperation::insert);
    d += move;
    system.unknowns_changed();
    system.assemble_residual();
    // R(d + m) - R(d) + K m (R = f_ext - f_int decreases by K m).
    VectorType noise = system.condensed_residual();
    noise -= before.condensed;
    VectorType response(d);
    response = 0;
    system.step_matrix().vmult(response, move);
    noise += response;
    for (const auto i : owned)
      if (constraints->is_constrained(i))
        noise[i] = 0;
    noise.compress(VectorOperation::insert);
    const double level = noise.l2_norm() / std::sqrt(2.);
    d                  = d_start;
    system.unknowns_changed();
    system.restore(before);
    return level;
  }

  void
  NewtonSolver::shift_diagonal(const double mu)
  {
    // Constrained rows carry only their diagonal; scaling it does not
    // change the solution there (AffineConstraints::distribute sets it).
    MatrixType &tangent = system.step_matrix();
    for (const auto i : system.unknowns().locally_owned_elements())
      tangent.add(i, i, mu * tangent.diag_element(i));
    tangent.compress(VectorOperation::add);
  }

  bool
  NewtonSolver::contact_conditions_hold(SolveStatistics &stats,
                                        const double     reference,
                                        unsigned int    &corrections)
  {
    // A converged state counts only if it meets the contact conditions
    // against the obstacle itself; otherwise what violates them is
    // released or let go and Newton goes on (within its iteration cap: a
    // peeling front may need a round per row of nodes).
    const double force_tolerance = parameters.newton_tolerance * reference;
    last_conditions = contact->check_conditions(system.ghosted_unknowns(),
                                                system.raw_residual(),
                                                force_tolerance);
    if (last_conditions.satisfied())
      return true;
    if (!contact->enforce_conditions(last_conditions,
                                     system.raw_residual(),
                                     force_tolerance))
      {
        stats.failure = contact->cycle_text().empty() ?
                          "the contact conditions cannot be met (after " +
                            std::to_string(corrections) +
                            " rounds of releases): " + last_conditions.text() :
                          "the contact set cycles (after " +
                            std::to_string(corrections) +
                            " rounds of releases): " + contact->cycle_text();
        return false;
      }
    ++corrections;
    pcout << "      contact conditions violated (" << last_conditions.text()
          << "): corrected" << contact->progress_text() << std::endl;
    return false;
  }

  NewtonSolver::State
  NewtonSolver::convergence_check(SolveStatistics &stats,
                                  const double     residual,
                                  const double     reference,
                                  const bool       set_changed,
                                  unsigned int    &corrections)
  {
    const double tol = parameters.newton_tolerance;
    if (!std::isfinite(residual) || !std::isfinite(reference))
      {
        stats.failure =
          format_text("the residual is not a finite number (|R| = "
                      "%g N, |f| = %g N): the loads or the material "
                      "values overflow double precision",
                      residual,
                      reference);
        return State::failed;
      }
    // Above the tolerance, a stalled Newton counts as converged only where
    // the residual is at the round-off level of its state, measured
    // (measure_round_off(): what one ulp of every displacement makes).
    bool floor = false;
    if (residual > tol * reference &&
        stalled(stats.residual_history, residual / reference))
      {
        if (stats.round_off == 0)
          stats.round_off =
            std::hypot(measure_round_off(), stats.linear_residual) / reference;
        floor = residual / reference <= round_off_margin * stats.round_off;
      }
    // Releases the active nodes that pull on the obstacle, if any.
    const auto release_pulling = [&](const std::string &when) {
      if (!contact->thaw_if_adhesive(system.raw_residual()))
        return false;
      start_new_history(stats);
      pcout << "      active nodes pull on the obstacle: released" << when
            << contact->progress_text() << std::endl;
      return true;
    };
    if (contact != nullptr && !set_changed && !floor &&
        residual > tol * reference &&
        residual <= release_check_residual * reference &&
        release_pulling(" before convergence"))
      return State::released;
    if (!((residual <= tol * reference || floor) &&
          (contact == nullptr || (!set_changed && contact->is_satisfied()))))
      return State::iterate;
    stats.at_round_off = floor;
    if (floor)
      pcout << format_text("      Newton: |R|/|f| = %.2e is at the round-off "
                           "level of this state (measured: %.2e, the noise of "
                           "evaluating the residual); tolerance %.0e not met, "
                           "converged at the round-off level",
                           residual / reference,
                           stats.round_off,
                           tol)
            << std::endl;
    if (contact == nullptr)
      return State::converged;
    if (release_pulling(""))
      return State::released;
    if (contact_conditions_hold(stats, reference, corrections))
      return State::converged;
    start_new_history(stats);
    return stats.failure.empty() ? State::released : State::failed;
  }

  unsigned int
  NewtonSolver::linear_step(const double               residual,
                            const double               target,
                            std::pair<double, double> &previous,
                            SolveStatistics           &stats)
  {
    update = 0;
    const double eta =
      linear_tolerance(residual, previous.first, previous.second, target);
    previous = {residual, eta};
    // The forcing term bounds the linear residual by eta |R|. The
    // right-hand side also carries the constraints' inhomogeneities (a
    // contact node brought onto the obstacle, a node following its
    // surface), which can exceed |R| by orders: eta relative to it would
    // let the step miss what Newton needs (seen: P2 brain on the skull at
    // 0.25 g along -y, stalled at |R|/|f| = 8.5e-7 by CG solves to 1e-1 of
    // such a right-hand side, converged with them held to eta |R|).
    const VectorType &rhs      = system.step_rhs();
    MatrixType       &tangent  = system.step_matrix();
    const double      rhs_norm = rhs.l2_norm();
    const double      relative =
      rhs_norm > residual ?
             std::max(parameters.linear_tolerance, eta * residual / rhs_norm) :
             eta;
    unsigned int iterations = 0;
    {
      TimerOutput::Scope scope(timer, "Linear solve");
      iterations = linear_solver->solve(tangent, update, rhs, relative);
      stats.linear_iterations += iterations;
    }
    // What an exact (direct) solve leaves: the floor below which this
    // step cannot bring the residual (backward error eps |K| |delta|, far
    // above the residual's own round-off on ill-conditioned systems).
    if (linear_solver->solves_prepared_exactly())
      {
        VectorType r = rhs;
        tangent.vmult(r, update);
        r -= rhs;
        stats.linear_residual = r.l2_norm();
      }
    constraints->distribute(update);
    ++stats.newton_iterations;
    return iterations;
  }

  NewtonSolver::LineSearchResult
  NewtonSolver::line_search(const double    residual,
                            const double    reference,
                            const bool      set_changed,
                            NewtonWatchdog *watchdog)
  {
    // Merit: the total potential energy (Armijo), which the Newton
    // direction descends where the tangent is positive definite; or, where
    // the energy cannot resolve the change (near convergence) or the
    // tangent is indefinite, the residual norm. A step that changes the
    // contact constraints is taken whole (as far as contact allows: no
    // step carries the body through the obstacle).
    const double     tol          = parameters.newton_tolerance;
    const double     energy_start = system.energy();
    const double     slope        = -(system.condensed_residual() * update);
    VectorType      &d            = system.unknowns();
    const VectorType d_start      = d;
    LineSearchResult ls;
    ls.alpha_max = contact != nullptr ? contact->max_step(update) : 1.;
    ls.alpha     = ls.alpha_max;
    for (unsigned int trial = 0; trial < line_search_trials;
         ++trial, ls.alpha *= 0.5)
      {
        d = d_start;
        d.add(ls.alpha, update);
        system.unknowns_changed();
        if (!system.assemble_residual())
          {
            ++ls.inverted_trials;
            continue;
          }
        ls.trial_residual = system.condensed_residual().l2_norm();
        ls.accepted       = (ls.alpha == ls.alpha_max && set_changed) ||
                      ls.trial_residual <= (1 - armijo * ls.alpha) * residual ||
                      ls.trial_residual <= tol * reference ||
                      (slope < 0 && system.energy() <=
                                      energy_start + armijo * ls.alpha * slope);
        if (ls.accepted)
          return ls;
        // A full step the energy rejects may still be the way to the
        // solution: the watchdog (if given) takes it on trial.
        if (trial == 0 && watchdog != nullptr && slope < 0 &&
            watchdog->may_let_through() && std::isfinite(ls.trial_residual) &&
            std::isfinite(system.energy()))
          {
            watchdog->let_through(d_start, energy_start + armijo * slope);
            ls.accepted    = true;
            ls.let_through = true;
            return ls;
          }
      }
    d = d_start;
    system.unknowns_changed();
    return ls;
  }

  void
  NewtonSolver::restore_checkpoint(const NewtonWatchdog &watchdog,
                                   SolveStatistics      &stats)
  {
    pcout << "      watchdog: the energy stayed above the target of the "
             "full step taken on trial for "
          << watchdog.trial_steps()
          << " steps: back to the state before it, with the line search"
          << std::endl;
    system.unknowns() = watchdog.checkpoint();
    system.unknowns_changed();
    system.unknowns_restarted();
    start_new_history(stats);
  }

  void
  NewtonSolver::print_step(const unsigned int      it,
                           const double            relative_residual,
                           const double            reference,
                           const LineSearchResult &ls,
                           const unsigned int      linear_iterations,
                           const double            shift) const
  {
    pcout << "      Newton " << std::setw(2) << it
          << format_text(": |R|/|f| %9.3e -> %9.3e, step %5.3f",
                         relative_residual,
                         ls.accepted ? ls.trial_residual / reference :
                                       relative_residual,
                         ls.alpha)
          << (ls.inverted_trials > 0 ?
                " (" + std::to_string(ls.inverted_trials) +
                  " shorter: a cell inverted)" :
                std::string())
          << (linear_solver_type == LinearSolverType::cg_amg ?
                ", " + linear_solver->last_method + " " +
                  std::to_string(linear_iterations) + " its" :
                std::string())
          << (contact != nullptr ? contact->progress_text() : std::string())
          << (shift > 0 ? format_text(", shift %.0e", shift) : std::string())
          << (ls.let_through ? ", on trial (the energy rose)" : "")
          << std::endl;
    set_progress_phase("Newton step " + std::to_string(it + 1) +
                       ": assembly and linear solve");
  }

  std::string
  NewtonSolver::shift_failure(const double relative_residual,
                              const bool   inverted) const
  {
    return format_text("Newton stalls at |R|/|f| = %.3e: its steps stay "
                       "short even with the tangent's diagonal scaled by "
                       "1 + %.0e (the largest shift tried)",
                       relative_residual,
                       TangentStrategy::max_shift) +
           (inverted ?
              "; the last shortened step: " + system.inverted_cells_text() :
              std::string());
  }

  bool
  NewtonSolver::retry_rejected_step(TangentStrategy        &strategy,
                                    const LineSearchResult &ls,
                                    const double            residual,
                                    const double            reference,
                                    SolveStatistics        &stats)
  {
    const TangentStrategy::Retry retry = strategy.rejected();
    system.set_tangent_type(strategy.tangent());
    switch (retry)
      {
        case TangentStrategy::Retry::larger_shift:
          pcout << "      no step along this tangent helps: the "
                   "diagonal shift raised, from the same state"
                << std::endl;
          return true;
        case TangentStrategy::Retry::projected:
          pcout << "      no step along the consistent tangent helps: "
                   "the projected one from the same state"
                << std::endl;
          return true;
        case TangentStrategy::Retry::shift_exhausted:
          stats.failure =
            shift_failure(residual / reference, ls.inverted_trials > 0);
          return false;
        case TangentStrategy::Retry::none:
          break;
      }
    stats.failure        = format_text("the line search could not reduce the "
                                       "residual (|R|/|f| = %.3e)",
                                residual / reference);
    stats.cells_inverted = ls.inverted_trials > 0;
    if (stats.cells_inverted)
      stats.failure += format_text("; %.0f of its %.0f trial steps inverted "
                                   "cells, the shortest of them ",
                                   ls.inverted_trials,
                                   line_search_trials) +
                       system.inverted_cells_text();
    return false;
  }

  bool
  NewtonSolver::solve(SolveStatistics &stats)
  {
    const double tol = parameters.newton_tolerance;
    if (contact != nullptr)
      contact->begin_solve(system.ghosted_unknowns());
    // Each attempt (a load step, its halvings) is judged on its own: a
    // failure left from an earlier attempt would fail this one at its first
    // contact correction.
    stats.failure.clear();
    system.unknowns_restarted();
    stats.cells_inverted = false;
    stats.at_round_off   = false;
    stats.round_off      = 0;
    stats.residual_history.clear();
    double reference = 0;
    // Inexact Newton: the previous step's residual and linear tolerance.
    std::pair<double, double> previous{0, 0};
    TangentStrategy strategy(configured_tangent, parameters.tangent_shift);
    NewtonWatchdog  watchdog(parameters.watchdog_steps);
    // The last pass only checks convergence: the state the last allowed
    // step reached counts.
    const unsigned int max_steps = parameters.max_newton_iterations;
    // Rounds of enforce_conditions() after converged states that violated
    // the contact conditions.
    unsigned int corrections = 0;
    // The steps that solved a linear system, as numbered on screen (a
    // release round between two of them takes a pass of the loop, not a
    // step).
    unsigned int step = 0;
    for (unsigned int it = 1; it <= max_steps + 1; ++it)
      {
        bool set_changed = false;
        if (contact != nullptr)
          {
            set_changed = contact->update_active_set(system.ghosted_unknowns(),
                                                     system.raw_residual(),
                                                     it == 1);
            stats.active_set_changes += set_changed;
            if (set_changed)
              start_new_history(stats);
          }
        constraints = &system.make_step_constraints();
        system.set_tangent_type(strategy.tangent());
        if (!system.assemble_step())
          {
            stats.failure =
              "at the start of the Newton step " + system.inverted_cells_text();
            return false;
          }
        if (strategy.shift() > 0)
          shift_diagonal(strategy.shift());
        const double residual = system.condensed_residual().l2_norm();
        if (reference == 0)
          reference = system.external_forces().l2_norm();
        if (reference == 0)
          reference = std::max(residual, 1e-300);
        stats.residual  = residual;
        stats.reference = reference;

        const State state = convergence_check(
          stats, residual, reference, set_changed, corrections);
        if (state == State::converged || state == State::failed)
          {
            // What follows is the caller's (output, error estimate), not
            // another Newton step.
            set_progress_phase("after the Newton solve");
            return state == State::converged;
          }
        if (it > max_steps)
          break;
        // Released contact constraints: the next step needs the new ones (a
        // step with those of this state would solve for nothing).
        if (state == State::released)
          continue;
        // A Newton that cannot reach the tolerance in the steps it has left
        // gives the load step back now (to be halved), not after them all.
        const std::string stagnates = stagnation(stats.residual_history,
                                                 residual / reference,
                                                 max_steps + 1 - it,
                                                 tol,
                                                 max_steps);
        if (!stagnates.empty())
          {
            stats.failure = stagnates;
            return false;
          }

        const unsigned int linear_iterations =
          linear_step(residual, tol * reference, previous, stats);
        const double shift = strategy.shift();
        // Trials only along Newton's own direction: the exact tangent,
        // unshifted, and without contact (going back would have to restore
        // the active set).
        const bool exact_newton = contact == nullptr && shift == 0 &&
                                  strategy.tangent() == TangentType::consistent;
        const bool             whole = set_changed || (contact != nullptr &&
                                           contact->moves_nodes_onto_surface());
        const LineSearchResult ls    = line_search(
          residual, reference, whole, exact_newton ? &watchdog : nullptr);
        print_step(++step,
                   residual / reference,
                   reference,
                   ls,
                   linear_iterations,
                   shift);
        if (!ls.accepted)
          {
            if (watchdog.abandon())
              {
                restore_checkpoint(watchdog, stats);
                continue;
              }
            if (retry_rejected_step(strategy, ls, residual, reference, stats))
              continue;
            return false;
          }
        if (!ls.let_through &&
            watchdog.judge(system.energy()) ==
              NewtonWatchdog::Verdict::restore &&
            ls.trial_residual > tol * reference)
          {
            restore_checkpoint(watchdog, stats);
            continue;
          }
        stats.residual_history.push_back(ls.trial_residual / reference);
        const bool within_shift = strategy.accepted(ls.alpha < ls.alpha_max);
        system.set_tangent_type(strategy.tangent());
        if (!within_shift)
          {
            stats.failure = shift_failure(ls.trial_residual / reference,
                                          ls.inverted_trials > 0);
            return false;
          }
      }
    stats.failure =
      "no convergence in " + std::to_string(max_steps) +
      format_text(" Newton iterations (|R|/|f| = %.3e, tolerance %.1e)",
                  stats.residual / stats.reference,
                  tol);
    if (contact != nullptr && stats.residual <= tol * stats.reference)
      stats.failure +=
        ": the residual meets the tolerance but " + contact->unsettled_text();
    return false;
  }
} // namespace RestShape
