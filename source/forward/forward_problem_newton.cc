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
  ForwardProblem::factorise_consistent_tangent(VectorType       &x,
                                               const VectorType &b)
  {
    const TangentType chosen = tangent_type;
    tangent_type             = TangentType::consistent;
    const bool valid         = assemble(Assemble::residual_and_matrix);
    tangent_type             = chosen;
    AssertThrow(valid, ExcMessage("an inverted cell in an equilibrium"));
    linear_solver->solve(tangent, x, b);
  }

  void
  ForwardProblem::solve_with_tangent(VectorType &x, const VectorType &b)
  {
    linear_solver->solve_factored(x, b);
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

  bool
  ForwardProblem::newton(SolveStatistics &stats)
  {
    const double tol = parameters.solver.newton_tolerance;
    if (contact != nullptr)
      contact->begin_solve(d_ghost);
    stats.cells_inverted = false;

    double reference = 0;
    // Inexact Newton: the previous step's residual and linear tolerance.
    double previous_residual = 0, previous_eta = 0;
    stats.residual_history.clear();
    // adaptive: the consistent tangent, but after a step the line search
    // had to shorten, one step with the projected one.
    const TangentType chosen = parameters.discretization.tangent;
    // Tangent shift > 0 (adaptive only): Levenberg-Marquardt instead of the
    // projected step; mu is the current relative diagonal shift.
    const double mu_start =
      chosen == TangentType::adaptive ? parameters.solver.tangent_shift : 0.;
    double mu = 0;
    // Beyond this shift a step is below 1e-4 of a Jacobi step: raising it
    // further cannot help (measured: P2 at gravity x 10 raised it to 1e95
    // in 90 useless steps per load increment; increments that converged
    // never needed more than 1). Then the Newton solve fails, and the load
    // increment is halved.
    const double mu_cap = 1e4;
    const auto   raise  = [&]() {
      mu = mu == 0 ? mu_start : 10 * mu;
      return mu <= mu_cap;
    };
    // inverted: the step's line search met inverted cells (the last of
    // them is in inverted_cells).
    const auto shift_failure = [&](const double residual, const bool inverted) {
      return format("Newton stalls at |R|/|f| = %.3e: its steps stay "
                    "short even with the tangent's diagonal scaled by "
                    "1 + %.0e (the largest shift tried)",
                    residual / reference,
                    mu_cap) +
             (inverted ? "; the last shortened step: " + inverted_cells_text() :
                         std::string());
    };
    tangent_type =
      chosen == TangentType::adaptive ? TangentType::consistent : chosen;
    // The last pass only checks convergence: the state the last allowed
    // step reached counts (it used to be thrown away at the cap even when
    // it met the tolerance).
    const unsigned int max_steps = parameters.solver.max_newton_iterations;
    // Step lengths tried by the line search: 1, 1/2, ..., 1/2^11.
    const unsigned int line_search_trials = 12;
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

        if (!assemble(Assemble::residual_and_matrix))
          {
            stats.failure =
              "at the start of the Newton step " + inverted_cells_text();
            return false;
          }
        if (mu > 0)
          shift_diagonal(mu);
        const double residual = residual_condensed.l2_norm();
        if (reference == 0)
          reference = external_condensed.l2_norm();
        if (reference == 0)
          reference = std::max(residual, 1e-300);
        stats.residual  = residual;
        stats.reference = reference;

        const bool floor =
          residual > tol * reference &&
          at_round_off_floor(stats.residual_history, residual / reference, tol);
        if ((residual <= tol * reference || floor) &&
            (contact == nullptr || (!set_changed && contact->is_satisfied())))
          {
            if (floor)
              pcout << format("      Newton: |R|/|f| = %.2e has stopped "
                              "decreasing (round-off; tolerance %.0e): "
                              "converged there",
                              residual / reference,
                              tol)
                    << std::endl;
            if (contact == nullptr)
              return true;
            if (contact->thaw_if_adhesive(residual_raw))
              pcout << "      active nodes pull on the obstacle: released"
                    << contact->progress_text() << std::endl;
            else if (contact_conditions_hold(stats, reference, corrections))
              return true;
            else if (!stats.failure.empty())
              return false;
          }
        if (it > max_steps)
          break;

        newton_update                  = 0;
        unsigned int linear_iterations = 0;
        const double eta               = linear_tolerance(residual,
                                            previous_residual,
                                            previous_eta,
                                            tol * reference);
        previous_residual              = residual;
        previous_eta                   = eta;
        {
          TimerOutput::Scope scope(timer, "Linear solve");
          linear_iterations =
            linear_solver->solve(tangent, newton_update, rhs_newton, eta);
          stats.linear_iterations += linear_iterations;
        }
        constraints_newton.distribute(newton_update);
        ++stats.newton_iterations;

        // Backtracking. Merit: the total potential energy (Armijo), which
        // the Newton direction descends where the tangent is positive
        // definite; or, where the energy cannot resolve the change (near
        // convergence) or the tangent is indefinite, the residual norm. A
        // step that changes the contact constraints is taken whole (as far
        // as contact allows: no step carries the body through the
        // obstacle).
        const double     energy_start = total_energy;
        const double     slope        = -(residual_condensed * newton_update);
        const VectorType d_start      = d;
        const double     alpha_max =
          contact != nullptr ? contact->max_step(newton_update) : 1.;
        double       alpha           = alpha_max;
        bool         accepted        = false;
        double       trial_residual  = 0;
        unsigned int inverted_trials = 0;
        for (unsigned int ls = 0; ls < line_search_trials && !accepted;
             ++ls, alpha *= 0.5)
          {
            d = d_start;
            d.add(alpha, newton_update);
            d_ghost = d;
            if (!assemble(Assemble::residual))
              {
                ++inverted_trials;
                continue;
              }
            trial_residual = residual_condensed.l2_norm();
            accepted       = (alpha == alpha_max && set_changed) ||
                       trial_residual <= (1 - 1e-4 * alpha) * residual ||
                       trial_residual <= tol * reference ||
                       (slope < 0 &&
                        total_energy <= energy_start + 1e-4 * alpha * slope);
            if (accepted)
              break;
          }
        pcout << "      Newton " << std::setw(2) << it
              << format(": |R|/|f| %9.3e -> %9.3e, step %5.3f",
                        residual / reference,
                        (accepted ? trial_residual : residual) / reference,
                        alpha)
              << (inverted_trials > 0 ? " (" + std::to_string(inverted_trials) +
                                          " shorter: a cell inverted)" :
                                        std::string())
              << (linear_solver_type == LinearSolverType::cg_amg ?
                    ", " + linear_solver->last_method + " " +
                      std::to_string(linear_iterations) + " its" :
                    std::string())
              << (contact != nullptr ? contact->progress_text() : std::string())
              << (mu > 0 ? format(", shift %.0e", mu) : std::string())
              << std::endl;
        if (accepted)
          {
            stats.residual_history.push_back(trial_residual / reference);
            if (mu_start > 0)
              {
                if (alpha < alpha_max)
                  {
                    if (!raise())
                      {
                        stats.failure =
                          shift_failure(trial_residual, inverted_trials > 0);
                        return false;
                      }
                  }
                else
                  mu = mu < 1e-3 * mu_start ? 0 : 0.1 * mu;
              }
            else if (chosen == TangentType::adaptive)
              tangent_type =
                (tangent_type == TangentType::consistent && alpha < alpha_max) ?
                  TangentType::projected :
                  TangentType::consistent;
          }
        else if (chosen == TangentType::adaptive &&
                 tangent_type == TangentType::consistent)
          {
            // No step along the consistent direction helps: from the same
            // state, a larger shift (Tangent shift > 0) or the projected
            // tangent.
            d       = d_start;
            d_ghost = d;
            if (mu_start > 0)
              {
                if (!raise())
                  {
                    stats.failure =
                      shift_failure(residual, inverted_trials > 0);
                    return false;
                  }
                pcout << "      no step along this tangent helps: the "
                         "diagonal shift raised, from the same state"
                      << std::endl;
              }
            else
              {
                pcout << "      no step along the consistent tangent helps: "
                         "the projected one from the same state"
                      << std::endl;
                tangent_type = TangentType::projected;
              }
            continue;
          }
        if (!accepted)
          {
            d       = d_start;
            d_ghost = d;
            stats.failure =
              format("the line search could not reduce the residual "
                     "(|R|/|f| = %.3e)",
                     residual / reference);
            stats.cells_inverted = inverted_trials > 0;
            if (stats.cells_inverted)
              stats.failure +=
                format("; %.0f of its %.0f trial steps inverted cells, the "
                       "shortest of them ",
                       inverted_trials,
                       line_search_trials) +
                inverted_cells_text();
            return false;
          }
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
        current_load.acceleration =
          start_load.acceleration +
          s * (target_load.acceleration - start_load.acceleration);
        current_load.pressure =
          start_load.pressure +
          s * (target_load.pressure - start_load.pressure);
        w = w_start;
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
            current_load.acceleration =
              start_load.acceleration +
              steps.done * (target_load.acceleration - start_load.acceleration);
            current_load.pressure =
              start_load.pressure +
              steps.done * (target_load.pressure - start_load.pressure);
            w = w_start;
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
