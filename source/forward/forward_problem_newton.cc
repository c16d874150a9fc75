// ForwardProblem: Newton's method with line search (and inexact linear
// tolerances), inside load stepping.

#include <restshape/base/input_error.h>
#include <restshape/base/units.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/forward/newton_progress.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

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
                  mm_per_m * center[0],
                  mm_per_m * center[1],
                  mm_per_m * center[2]);
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
  ForwardProblem::solve_with_tangent(VectorType       &x,
                                     const VectorType &b,
                                     const double      tolerance)
  {
    linear_solver->solve_prepared(x, b, tolerance);
  }

  bool
  ForwardProblem::tangent_solves_are_exact() const
  {
    return linear_solver->solves_prepared_exactly();
  }

  double
  ForwardProblem::measure_round_off()
  {
    // The residual at displacements moved by about the smallest change the
    // state resolves (an ulp of d, or of F = I + grad d: eps h_min) at every
    // free DoF, less the tangent's linear response to that move: what is
    // left is the noise of evaluating the residual (at small strains, of
    // the co-rotational stress 2 mu (F - R): eps against the strain), the
    // level below which no Newton step can bring it. Needs the tangent of
    // the current state (the top of a Newton step).
    const VectorType d_start = d, raw = residual_raw,
                     condensed = residual_condensed,
                     external  = external_condensed;
    const double energy        = total_energy;
    const double resolution    = std::numeric_limits<double>::epsilon() *
                              labelled_mesh.minimum_cell_diameter();
    VectorType move = zero_vector();
    for (const auto i : owned_dofs)
      if (!constraints_newton.is_constrained(i))
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
    d_ghost = d;
    assemble(Assemble::residual);
    // R(d + m) - R(d) + K m (R = f_ext - f_int decreases by K m).
    VectorType noise = residual_condensed;
    noise -= condensed;
    VectorType response = zero_vector();
    tangent.vmult(response, move);
    noise += response;
    for (const auto i : owned_dofs)
      if (constraints_newton.is_constrained(i))
        noise[i] = 0;
    noise.compress(VectorOperation::insert);
    const double level = noise.l2_norm() / std::sqrt(2.);
    d                  = d_start;
    d_ghost            = d;
    residual_raw       = raw;
    residual_condensed = condensed;
    external_condensed = external;
    total_energy       = energy;
    return level;
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
          << "): released" << contact->progress_text() << std::endl;
    return false;
  }

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
  } // namespace

  ForwardProblem::NewtonState
  ForwardProblem::convergence_check(SolveStatistics &stats,
                                    const double     residual,
                                    const double     reference,
                                    const bool       set_changed,
                                    unsigned int    &corrections)
  {
    const double tol = parameters.solver.newton_tolerance;
    if (!std::isfinite(residual) || !std::isfinite(reference))
      {
        stats.failure = format("the residual is not a finite number (|R| = "
                               "%g N, |f| = %g N): the loads or the material "
                               "values overflow double precision",
                               residual,
                               reference);
        return NewtonState::failed;
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
    if (!((residual <= tol * reference || floor) &&
          (contact == nullptr || (!set_changed && contact->is_satisfied()))))
      return NewtonState::iterate;
    stats.at_round_off = floor;
    if (floor)
      pcout << format("      Newton: |R|/|f| = %.2e is at the round-off "
                      "level of this state (measured: %.2e, the noise of "
                      "evaluating the residual); tolerance %.0e not met, "
                      "converged at the round-off level",
                      residual / reference,
                      stats.round_off,
                      tol)
            << std::endl;
    if (contact == nullptr)
      return NewtonState::converged;
    // A change of the constraints starts a new convergence history.
    const auto new_history = [&stats]() {
      stats.residual_history.clear();
      stats.round_off = 0;
    };
    if (contact->thaw_if_adhesive(residual_raw))
      {
        new_history();
        pcout << "      active nodes pull on the obstacle: released"
              << contact->progress_text() << std::endl;
        return NewtonState::iterate;
      }
    if (contact_conditions_hold(stats, reference, corrections))
      return NewtonState::converged;
    new_history();
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
    previous = {residual, eta};
    // The forcing term bounds the linear residual by eta |R|. The
    // right-hand side also carries the constraints' inhomogeneities (a
    // contact node brought onto the obstacle, a node following its
    // surface), which can exceed |R| by orders: eta relative to it would
    // let the step miss what Newton needs (seen: P2 brain on the skull at
    // 0.25 g along -y, stalled at |R|/|f| = 8.5e-7 by CG solves to 1e-1 of
    // such a right-hand side, converged with them held to eta |R|).
    const double rhs_norm   = rhs_newton.l2_norm();
    const double relative   = rhs_norm > residual ?
                                std::max(parameters.solver.linear_tolerance,
                                       eta * residual / rhs_norm) :
                                eta;
    unsigned int iterations = 0;
    {
      TimerOutput::Scope scope(timer, "Linear solve");
      iterations =
        linear_solver->solve(tangent, newton_update, rhs_newton, relative);
      stats.linear_iterations += iterations;
    }
    // What an exact (direct) solve leaves: the floor below which this
    // step cannot bring the residual (backward error eps |K| |delta|, far
    // above the residual's own round-off on ill-conditioned systems).
    if (linear_solver->solves_prepared_exactly())
      {
        VectorType r = rhs_newton;
        tangent.vmult(r, newton_update);
        r -= rhs_newton;
        stats.linear_residual = r.l2_norm();
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
    // Each attempt (a load step, its halvings) is judged on its own: a
    // failure left from an earlier attempt would fail this one at its first
    // contact correction.
    stats.failure.clear();
    stats.cells_inverted = false;
    stats.at_round_off   = false;
    stats.round_off      = 0;
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
            if (set_changed)
              {
                stats.residual_history.clear();
                stats.round_off = 0;
              }
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

  std::string
  ForwardProblem::give_up_text(const SolveStatistics &stats,
                               const FailedAttempts  &failed,
                               const unsigned int     halvings) const
  {
    // Where the load stepping stopped and how compressed its equilibrium
    // is, then what failed beyond it: steps that inverted cells (with one
    // of them), and the last failure.
    const Compression c = most_compressed_cell();
    std::string       text =
      format("gave up at %.4f of the full load "
             "(its equilibrium compresses cells to "
             "det F = %.3g, ",
             stats.fraction,
             c.det_F) +
      c.where + ") after " + std::to_string(halvings - 1) +
      " halvings of the load increment: " + std::to_string(failed.count) +
      " failed attempts";
    if (failed.inverting > 0)
      text += ", " + std::to_string(failed.inverting) +
              format(" of them because Newton's steps inverted cells (towards "
                     "%.4g of the load: ",
                     failed.inverting_fraction) +
              failed.inverting_text + ")";
    text += "; the last one: " + stats.failure;
    // Measured on the stability matrix (doc/benchmarks.md, section 4):
    // every P1 case converged with the shift. Not where the last increment
    // failed because its steps invert cells (P2 at gravity x 10: the shift
    // only took longer to fail).
    if (parameters.discretization.tangent == TangentType::adaptive &&
        parameters.solver.tangent_shift == 0 && failed.inverting == 0)
      text += " (Solver/Tangent shift = 1e-3 may help)";
    return text;
  }

  SolveStatistics
  ForwardProblem::solve(const LoadState &target_load, const VectorType &rest)
  {
    SolveStatistics  stats;
    const LoadState  start_load  = current_load;
    const VectorType w_start     = w;
    VectorType       d_converged = d;
    LoadSteps        steps{0, 1. / parameters.solver.initial_load_steps};
    unsigned int     halvings = 0;
    FailedAttempts   failed;
    ActiveSetConstraints::State contact_converged;
    if (contact != nullptr)
      contact_converged = contact->state();

    const auto set_fraction = [&](const double s) {
      current_load = between(start_load, target_load, s);
      w            = w_start;
      w.sadd(1 - s, s, rest);
      w_ghost = w;
    };
    while (steps.done < 1)
      {
        const double s = steps.next();
        set_fraction(s);
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
        failed.add(s, stats.cells_inverted, inverted_cells_text());
        // Back to the last equilibrium, smaller increment.
        d       = d_converged;
        d_ghost = d;
        if (contact != nullptr)
          contact->set_state(contact_converged);
        if (++halvings > parameters.solver.max_load_step_halvings)
          {
            set_fraction(steps.done);
            stats.fraction = steps.done;
            stats.failure  = give_up_text(stats, failed, halvings);
            pcout << "    Newton failed: " << stats.failure << std::endl;
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
