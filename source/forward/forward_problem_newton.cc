// ForwardProblem: Newton's method with line search (and inexact linear
// tolerances), inside load stepping.

#include <restshape/base/input_error.h>
#include <restshape/contact/contact.h>
#include <restshape/forward/forward_problem.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    std::string
    format(const char *fmt, double a, double b = 0, double c = 0)
    {
      char buffer[256];
      std::snprintf(buffer, sizeof(buffer), fmt, a, b, c);
      return buffer;
    }

    /**
     * Whether Newton has reached its round-off floor: the relative
     * residual @p now is within a factor of 100 of the tolerance @p tol and
     * the relative residuals @p history of the accepted steps (the last one
     * led to @p now) have not halved over the last five steps (seen:
     * 2.4e-10 to 3.3e-10 for 46 steps against 1e-10 on 140k DoFs).
     */
    bool
    at_round_off_floor(const std::vector<double> &history,
                       const double               now,
                       const double               tol)
    {
      const unsigned int window       = 5;
      const double       floor_factor = 100;
      // The last accepted step must have led to this very state (not a
      // state a contact update has changed since).
      if (now > floor_factor * tol || history.size() <= window ||
          std::abs(history.back() - now) > 1e-6 * now)
        return false;
      const double before = history[history.size() - 1 - window];
      return *std::min_element(history.end() - window, history.end()) >
             0.5 * before;
    }
  } // namespace

  // ------------------------------------------------------------------
  // Newton's method with line search, inside load stepping.

  std::string
  cell_location_text(const types::material_id label, const Point<3> &center)
  {
    char text[100];
    std::snprintf(text,
                  sizeof(text),
                  "label %u at (%.1f, %.1f, %.1f) mm of the mesh",
                  static_cast<unsigned int>(label),
                  1e3 * center[0],
                  1e3 * center[1],
                  1e3 * center[2]);
    return text;
  }

  std::string
  ForwardProblem::inverted_cells_text() const
  {
    return std::to_string(inverted_cells.count) +
           (inverted_cells.count == 1 ? " cell" : " cells") +
           " inverted (det F <= 0), e.g. " +
           cell_location_text(inverted_cells.label, inverted_cells.center);
  }


  double
  ForwardProblem::linear_tolerance(const double residual,
                                   const double previous_residual,
                                   const double previous_eta,
                                   const double target) const
  {
    const double fixed = parameters.solver.linear_tolerance;
    if (!parameters.solver.inexact_newton)
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

  void
  ForwardProblem::prepare_consistent_tangent()
  {
    const TangentType chosen = tangent_type;
    tangent_type             = TangentType::consistent;
    const bool valid         = assemble(Assemble::residual_and_matrix);
    tangent_type             = chosen;
    AssertThrow(valid, ExcMessage("an inverted cell in an equilibrium"));
    linear_solver->prepare(tangent);
  }

  void
  ForwardProblem::release_linear_solver()
  {
    linear_solver->release();
  }

  void
  ForwardProblem::solve_with_tangent(VectorType &x, const VectorType &b)
  {
    linear_solver->solve_prepared(x, b);
  }

  bool
  ForwardProblem::tangent_solves_are_exact() const
  {
    return linear_solver->solves_prepared_exactly();
  }

  void
  ForwardProblem::shift_diagonal(const double mu)
  {
    // Constrained rows carry only their diagonal; scaling it does not
    // change the solution there (AffineConstraints::distribute sets it).
    for (const auto i : owned_dofs)
      tangent.add(i, i, mu * tangent.diag_element(i));
    tangent.compress(VectorOperation::add);
  }

  bool
  ForwardProblem::contact_conditions_hold(SolveStatistics &stats,
                                          const double     reference,
                                          unsigned int    &corrections)
  {
    // A converged state counts only if it meets the contact conditions
    // against the obstacle itself; otherwise what violates them is
    // released or let go and Newton goes on (within its iteration cap: a
    // peeling front may need a round per row of nodes).
    const double force_tolerance =
      parameters.solver.newton_tolerance * reference;
    last_conditions =
      contact->check_conditions(d_ghost, residual_raw, force_tolerance);
    if (last_conditions.satisfied())
      return true;
    if (!contact->enforce_conditions(last_conditions,
                                     residual_raw,
                                     force_tolerance))
      {
        stats.failure = "the contact conditions cannot be met (after " +
                        std::to_string(corrections) +
                        " rounds of releases): " + last_conditions.text();
        return false;
      }
    ++corrections;
    pcout << "      contact conditions violated (" << last_conditions.text()
          << "): released" << contact->progress_text() << std::endl;
    return false;
  }

  namespace
  {
    /// Step lengths tried by the line search: 1, 1/2, ..., 1/2^11.
    constexpr unsigned int line_search_trials = 12;
    /// Armijo's sufficient decrease.
    constexpr double armijo = 1e-4;
  } // namespace

  ForwardProblem::NewtonState
  ForwardProblem::convergence_check(SolveStatistics &stats,
                                    const double     residual,
                                    const double     reference,
                                    const bool       set_changed,
                                    unsigned int    &corrections)
  {
    const double tol = parameters.solver.newton_tolerance;
    const bool   floor =
      residual > tol * reference &&
      at_round_off_floor(stats.residual_history, residual / reference, tol);
    if (!((residual <= tol * reference || floor) &&
          (contact == nullptr || (!set_changed && contact->is_satisfied()))))
      return NewtonState::iterate;
    if (floor)
      pcout << format("      Newton: |R|/|f| = %.2e has stopped "
                      "decreasing (round-off; tolerance %.0e): "
                      "converged there",
                      residual / reference,
                      tol)
            << std::endl;
    if (contact == nullptr)
      return NewtonState::converged;
    if (contact->thaw_if_adhesive(residual_raw))
      {
        pcout << "      active nodes pull on the obstacle: released"
              << contact->progress_text() << std::endl;
        return NewtonState::iterate;
      }
    if (contact_conditions_hold(stats, reference, corrections))
      return NewtonState::converged;
    return stats.failure.empty() ? NewtonState::iterate : NewtonState::failed;
  }

  unsigned int
  ForwardProblem::linear_step(const double               residual,
                              const double               target,
                              std::pair<double, double> &previous,
                              SolveStatistics           &stats)
  {
    newton_update = 0;
    const double eta =
      linear_tolerance(residual, previous.first, previous.second, target);
    previous                = {residual, eta};
    unsigned int iterations = 0;
    {
      TimerOutput::Scope scope(timer, "Linear solve");
      iterations =
        linear_solver->solve(tangent, newton_update, rhs_newton, eta);
      stats.linear_iterations += iterations;
    }
    constraints_newton.distribute(newton_update);
    ++stats.newton_iterations;
    return iterations;
  }

  ForwardProblem::LineSearchResult
  ForwardProblem::line_search(const double residual,
                              const double reference,
                              const bool   set_changed)
  {
    // Merit: the total potential energy (Armijo), which the Newton
    // direction descends where the tangent is positive definite; or, where
    // the energy cannot resolve the change (near convergence) or the
    // tangent is indefinite, the residual norm. A step that changes the
    // contact constraints is taken whole (as far as contact allows: no
    // step carries the body through the obstacle).
    const double     tol          = parameters.solver.newton_tolerance;
    const double     energy_start = total_energy;
    const double     slope        = -(residual_condensed * newton_update);
    const VectorType d_start      = d;
    LineSearchResult ls;
    ls.alpha_max = contact != nullptr ? contact->max_step(newton_update) : 1.;
    ls.alpha     = ls.alpha_max;
    for (unsigned int trial = 0; trial < line_search_trials;
         ++trial, ls.alpha *= 0.5)
      {
        d = d_start;
        d.add(ls.alpha, newton_update);
        d_ghost = d;
        if (!assemble(Assemble::residual))
          {
            ++ls.inverted_trials;
            continue;
          }
        ls.trial_residual = residual_condensed.l2_norm();
        ls.accepted       = (ls.alpha == ls.alpha_max && set_changed) ||
                      ls.trial_residual <= (1 - armijo * ls.alpha) * residual ||
                      ls.trial_residual <= tol * reference ||
                      (slope < 0 && total_energy <=
                                      energy_start + armijo * ls.alpha * slope);
        if (ls.accepted)
          return ls;
      }
    d       = d_start;
    d_ghost = d;
    return ls;
  }

  void
  ForwardProblem::print_newton_step(const unsigned int      it,
                                    const double            relative_residual,
                                    const double            reference,
                                    const LineSearchResult &ls,
                                    const unsigned int      linear_iterations,
                                    const double            shift) const
  {
    pcout << "      Newton " << std::setw(2) << it
          << format(": |R|/|f| %9.3e -> %9.3e, step %5.3f",
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
          << (shift > 0 ? format(", shift %.0e", shift) : std::string())
          << std::endl;
  }

  bool
  ForwardProblem::newton(SolveStatistics &stats)
  {
    const double tol = parameters.solver.newton_tolerance;
    if (contact != nullptr)
      contact->begin_solve(d_ghost);
    stats.cells_inverted = false;
    stats.residual_history.clear();
    double reference = 0;
    // Inexact Newton: the previous step's residual and linear tolerance.
    std::pair<double, double> previous{0, 0};
    TangentStrategy           strategy(parameters.discretization.tangent,
                             parameters.solver.tangent_shift);
    const auto shift_failure = [&](const double residual, const bool inverted) {
      return format("Newton stalls at |R|/|f| = %.3e: its steps stay "
                    "short even with the tangent's diagonal scaled by "
                    "1 + %.0e (the largest shift tried)",
                    residual / reference,
                    TangentStrategy::max_shift) +
             (inverted ? "; the last shortened step: " + inverted_cells_text() :
                         std::string());
    };
    // The last pass only checks convergence: the state the last allowed
    // step reached counts.
    const unsigned int max_steps = parameters.solver.max_newton_iterations;
    // Rounds of enforce_conditions() after converged states that violated
    // the contact conditions.
    unsigned int corrections = 0;
    for (unsigned int it = 1; it <= max_steps + 1; ++it)
      {
        bool set_changed = false;
        if (contact != nullptr)
          {
            set_changed =
              contact->update_active_set(d_ghost, residual_raw, it == 1);
            stats.active_set_changes += set_changed;
          }
        make_newton_constraints();
        tangent_type = strategy.tangent();
        if (!assemble(Assemble::residual_and_matrix))
          {
            stats.failure =
              "at the start of the Newton step " + inverted_cells_text();
            return false;
          }
        if (strategy.shift() > 0)
          shift_diagonal(strategy.shift());
        const double residual = residual_condensed.l2_norm();
        if (reference == 0)
          reference = external_condensed.l2_norm();
        if (reference == 0)
          reference = std::max(residual, 1e-300);
        stats.residual  = residual;
        stats.reference = reference;

        const NewtonState state = convergence_check(
          stats, residual, reference, set_changed, corrections);
        if (state != NewtonState::iterate)
          return state == NewtonState::converged;
        if (it > max_steps)
          break;

        const unsigned int linear_iterations =
          linear_step(residual, tol * reference, previous, stats);
        const double           shift = strategy.shift();
        const LineSearchResult ls =
          line_search(residual, reference, set_changed);
        print_newton_step(
          it, residual / reference, reference, ls, linear_iterations, shift);
        if (ls.accepted)
          {
            stats.residual_history.push_back(ls.trial_residual / reference);
            const bool within_shift =
              strategy.accepted(ls.alpha < ls.alpha_max);
            tangent_type = strategy.tangent();
            if (!within_shift)
              {
                stats.failure =
                  shift_failure(ls.trial_residual, ls.inverted_trials > 0);
                return false;
              }
            continue;
          }
        const TangentStrategy::Retry retry = strategy.rejected();
        tangent_type                       = strategy.tangent();
        switch (retry)
          {
            case TangentStrategy::Retry::larger_shift:
              pcout << "      no step along this tangent helps: the "
                       "diagonal shift raised, from the same state"
                    << std::endl;
              continue;
            case TangentStrategy::Retry::projected:
              pcout << "      no step along the consistent tangent helps: "
                       "the projected one from the same state"
                    << std::endl;
              continue;
            case TangentStrategy::Retry::shift_exhausted:
              stats.failure = shift_failure(residual, ls.inverted_trials > 0);
              return false;
            case TangentStrategy::Retry::none:
              break;
          }
        stats.failure        = format("the line search could not reduce the "
                                      "residual (|R|/|f| = %.3e)",
                               residual / reference);
        stats.cells_inverted = ls.inverted_trials > 0;
        if (stats.cells_inverted)
          stats.failure += format("; %.0f of its %.0f trial steps inverted "
                                  "cells, the shortest of them ",
                                  ls.inverted_trials,
                                  line_search_trials) +
                           inverted_cells_text();
        return false;
      }
    stats.failure =
      "no convergence in " + std::to_string(max_steps) +
      format(" Newton iterations (|R|/|f| = %.3e, tolerance %.1e)",
             stats.residual / stats.reference,
             tol);
    if (contact != nullptr && stats.residual <= tol * stats.reference)
      stats.failure +=
        ": the residual meets the tolerance but " + contact->unsettled_text();
    return false;
  }

  SolveStatistics
  ForwardProblem::solve(const LoadState &target_load, const VectorType &rest)
  {
    SolveStatistics       stats;
    const LoadState       start_load  = current_load;
    const VectorType      w_start     = w;
    VectorType            d_converged = d;
    LoadSteps             steps{0, 1. / parameters.solver.initial_load_steps};
    unsigned int          halvings = 0;
    ContactProblem::State contact_converged;
    if (contact != nullptr)
      contact_converged = contact->state();

    while (steps.done < 1)
      {
        const double s = steps.next();
        current_load   = between(start_load, target_load, s);
        w              = w_start;
        w.sadd(1 - s, s, rest);
        w_ghost = w;
        if (s < 1 || steps.increment < 1)
          pcout << "    Load step to " << format("%.4f", s) << std::endl;

        if (newton(stats))
          {
            steps.accept(s);
            d_converged = d;
            if (contact != nullptr)
              contact_converged = contact->state();
            ++stats.load_steps;
            continue;
          }
        // Back to the last equilibrium, smaller increment.
        d       = d_converged;
        d_ghost = d;
        if (contact != nullptr)
          contact->set_state(contact_converged);
        if (++halvings > parameters.solver.max_load_step_halvings)
          {
            current_load = between(start_load, target_load, steps.done);
            w            = w_start;
            w.sadd(1 - steps.done, steps.done, rest);
            w_ghost = w;
            stats.failure += "; gave up after " + std::to_string(halvings - 1) +
                             " halvings of the load increment at " +
                             format("%.4f", steps.done) + " of the full load";
            // Measured on the stability matrix (doc/benchmarks.md,
            // section 4): every P1 case converged with the shift. Not where
            // the last increment failed because its steps invert cells (P2
            // at gravity x 10: the shift only took longer to fail).
            if (parameters.discretization.tangent == TangentType::adaptive &&
                parameters.solver.tangent_shift == 0 && !stats.cells_inverted)
              stats.failure += " (Solver/Tangent shift = 1e-3 may help)";
            pcout << "    Newton failed: " << stats.failure << std::endl;
            stats.fraction = steps.done;
            return stats;
          }
        pcout << "    Newton failed (" << stats.failure
              << "); halving the increment" << std::endl;
        steps.reject(s);
      }
    stats.converged = true;
    stats.fraction  = 1;
    stats.failure.clear();
    return stats;
  }

  SolveStatistics
  ForwardProblem::solve_from(const VectorType *guess,
                             const LoadState  &load,
                             const VectorType &rest)
  {
    SolveStatistics first;
    if (guess != nullptr)
      {
        set_state(*guess, rest, load);
        if (contact != nullptr)
          contact->reset();
        if (newton(first))
          {
            first.converged  = true;
            first.fraction   = 1;
            first.load_steps = 1;
            first.failure.clear();
            return first;
          }
        pcout << "    Newton from the initial guess failed (" << first.failure
              << "); starting again from the unloaded state" << std::endl;
      }
    set_state(zero_vector(), zero_vector(), LoadState());
    if (contact != nullptr)
      contact->reset();
    SolveStatistics stats = solve(load, rest);
    stats.newton_iterations += first.newton_iterations;
    stats.linear_iterations += first.linear_iterations;
    stats.active_set_changes += first.active_set_changes;
    return stats;
  }

} // namespace RestShape
