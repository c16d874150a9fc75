// DirectInverse: Jacobian-free Newton on the equilibrium at the target
// with the rest shape as unknown (see direct_inverse.h).
#include <restshape/base/input_error.h>
#include <restshape/base/progress.h>
#include <restshape/inverse/direct_inverse.h>
#include <restshape/inverse/flexible_gmres.h>
#include <restshape/solver/newton_watchdog.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Newton stops at |R| <= this times |R| at the initial rest shape
    /// under the full load; on the way to the full load, at the looser
    /// step tolerance. (Not Solver/Newton tolerance, which measures |R|
    /// against the load vector: the forward solve of the fixed point that
    /// follows checks the rest shape against that one.)
    constexpr double       final_reduction  = 1e-9;
    constexpr double       step_tolerance   = 1e-6;
    constexpr unsigned int max_newton_steps = 15; // per load step
    /// A Newton step that keeps more than this of |R| makes slow progress;
    /// two in a row fail the load step (the rest shape's Newton step is
    /// not a good model of the residual there: large rotations).
    constexpr double slow_progress = 0.9;
    /// Load steps that may fail before the direct inverse gives up.
    constexpr unsigned int max_failed_load_steps = 3;
    /// GMRES reduces the linearised residual by the forcing term eta
    /// (inexact Newton; Eisenstat and Walker's choice 2: eta = gamma
    /// (|R_k| / |R_k-1|)^2, kept up by gamma eta_k-1^2 where that exceeds
    /// forcing_safeguard, at most max_forcing, and never below what reaches
    /// the tolerance: no oversolving far from the solution), in at most
    /// max_gmres_steps iterations.
    constexpr double       max_forcing       = 0.5;
    constexpr double       forcing_gamma     = 0.9;
    constexpr double       forcing_safeguard = 0.1;
    constexpr unsigned int max_gmres_steps   = 40;
    /// With CG + AMG the preconditioner is an inner CG solve to this
    /// relative tolerance (FGMRES tolerates inexact inner solves; looser
    /// ones take more outer products, tighter ones more CG iterations).
    constexpr double inner_tolerance = 1e-2;

    /// The next forcing term after a Newton step that took the relative
    /// residual from @p last to @p now, with the forcing term @p eta
    /// (max_forcing at the first step); @p tolerance is Newton's.
    double
    forcing_term(const double eta,
                 const double last,
                 const double now,
                 const double tolerance)
    {
      double next = max_forcing;
      if (last < std::numeric_limits<double>::max())
        {
          const double ratio = now / last;
          next               = forcing_gamma * ratio * ratio;
          const double kept  = forcing_gamma * eta * eta;
          if (kept > forcing_safeguard)
            next = std::max(next, kept);
        }
      // Half the tolerance is enough: the linear model need not be
      // solved further than the residual Newton stops at.
      return std::min(max_forcing, std::max(next, 0.5 * tolerance / now));
    }
    /// Finite-difference step: the largest nodal perturbation, as a
    /// fraction of the body's size.
    constexpr double fd_step = 1e-7;
    /// Line search: halvings, and the decrease it asks for (Armijo).
    constexpr unsigned int max_halvings = 10;
    constexpr double       armijo       = 1e-4;
    /// With the three-field pressures (ThreeFieldPressures), the steps a
    /// full step on trial has to reach its target at least: the condensed
    /// residual weighs each full step's second-order change of volume by
    /// the bulk modulus, which the next step removes, so |R| falls every
    /// other step (the inflated shell at nu = 0.4999, P2-P0, from half its
    /// load to all of it: 16 -> 0.82 -> 63 -> 5.1 -> 0.82 -> 0.0089 ->
    /// 9e-7: below its target after 6 steps).
    constexpr unsigned int three_field_trial_steps = 8;
  } // namespace

  unsigned int
  DirectInverse::trial_steps() const
  {
    const unsigned int steps = forward.scene_parameters().solver.watchdog_steps;
    return steps > 0 && pressures.enabled() ?
             std::max(steps, three_field_trial_steps) :
             steps;
  }

  double
  DirectInverse::difference_step(const VectorType &v) const
  {
    return fd_step * forward.discretization().mesh().diameter() /
           v.linfty_norm();
  }

  void
  DirectInverse::jacobian_product(const VectorType &w,
                                  const VectorType &r,
                                  const VectorType &v,
                                  VectorType       &trial,
                                  VectorType       &product)
  {
    product = 0;
    if (v.linfty_norm() == 0)
      return;
    const double e = difference_step(v);
    trial          = w;
    trial.add(e, v);
    residual(trial, product);
    product -= r;
    product /= e;
    ++result.jacobian_products;
  }

  DirectInverse::DirectInverse(ForwardProblem     &forward,
                               ConditionalOStream &pcout)
    : forward(forward)
    , pcout(pcout)
    , pressures(forward)
  {}

  void
  DirectInverse::set_target(const VectorType &displacement,
                            const VectorType &force)
  {
    target_displacement = displacement;
    obstacle_force      = force;
    const auto &fixed   = forward.discretization().base_constraints();
    for (const auto i : forward.discretization().locally_owned_dofs())
      if (fixed.is_constrained(i))
        obstacle_force[i] = 0;
    obstacle_force.compress(VectorOperation::insert);
  }

  bool
  DirectInverse::residual(const VectorType &w, VectorType &r)
  {
    forward.set_state(d, w, load);
    const bool valid = forward.evaluate();
    r                = forward.condensed_residual();
    if (obstacle_force.size() > 0)
      r.add(fraction, obstacle_force);
    return valid;
  }

  DirectInverseResult
  DirectInverse::solve(const LoadState &scene_load, VectorType &rest)
  {
    result       = DirectInverseResult();
    d            = target_displacement.size() > 0 ? target_displacement :
                                                    forward.discretization().zero_vector();
    load         = scene_load;
    fraction     = 1;
    VectorType r = forward.discretization().zero_vector();
    if (!residual(rest, r))
      {
        result.failure = "the initial rest shape has an inverted cell";
        return result;
      }
    reference = r.l2_norm();
    // Continuation in the load: a converged increment doubles the next,
    // a failed one is halved.
    double       done = 0, increment = 1;
    unsigned int failed = 0;
    while (done < 1)
      {
        const double s   = std::min(1., done + increment);
        VectorType   w   = rest;
        load             = between(LoadState(), scene_load, s);
        fraction         = s;
        const bool final = (s == 1);
        if (newton(w, final ? final_reduction : step_tolerance, s))
          {
            rest           = w;
            done           = s;
            increment      = std::min(2 * increment, 1.);
            result.failure = ""; // of an earlier, halved load step
            continue;
          }
        increment = (s - done) / 2;
        if (++failed == max_failed_load_steps)
          {
            result.failure += "; gave up after " + std::to_string(failed) +
                              " failed load steps, at " + number_text(done) +
                              " of the load";
            return result;
          }
        pcout << "  Direct inverse, load " << s << " failed (" << result.failure
              << "); next load " << done + increment << std::endl;
      }
    result.converged = true;
    return result;
  }

  bool
  DirectInverse::newton(VectorType &w, const double tolerance, const double s)
  {
    VectorType r = forward.discretization().zero_vector();
    pressures.forget(); // a new load: its own, consistent, pressures
    if (!residual(w, r))
      return false;
    // Full steps whose |R| lies above the line search's target are taken
    // on trial, as in the forward solve (Solver/Watchdog steps): the
    // first step of large rotations stretches the rest shape, the next
    // ones turn the stretch into the rotation.
    NewtonWatchdog watchdog(trial_steps());
    unsigned int   slow = 0;
    double         last = std::numeric_limits<double>::max(), eta = max_forcing;
    for (unsigned int step = 0;; ++step)
      {
        result.relative_residual = r.l2_norm() / reference;
        if (result.relative_residual <= tolerance)
          return true;
        slow = !watchdog.on_trial() &&
                   result.relative_residual > slow_progress * last ?
                 slow + 1 :
                 0;
        eta  = forcing_term(eta, last, result.relative_residual, tolerance);
        last = result.relative_residual;
        if (step == max_newton_steps || slow == 2)
          {
            result.failure =
              slow == 2 ? "two Newton steps in a row kept more than " +
                            std::to_string(int(100 * slow_progress)) +
                            " % of the residual" :
                          "no convergence in " +
                            std::to_string(max_newton_steps) + " Newton steps";
            return false;
          }
        const Direction direction = newton_direction(w, r, eta);
        // A trial's steps must be Newton steps: where GMRES cannot solve
        // their linear model the state is too far from the solution.
        if (pressures.enabled() && watchdog.on_trial() && !direction.solved)
          {
            result.failure = "GMRES did not solve a Newton step of a full "
                             "step on trial in " +
                             std::to_string(max_gmres_steps) + " iterations";
            return false;
          }
        const Step taken = line_search(w, r, direction.delta, watchdog);
        if (taken == Step::failed)
          {
            if (watchdog.abandon())
              result.failure = trial_failure(watchdog);
            return false;
          }
        ++result.newton_steps;
        pcout << "  Direct inverse, load " << s << ", Newton " << step + 1
              << ": |R|/|R0| " << last << " -> " << r.l2_norm() / reference
              << ", GMRES " << direction.products << " its to " << eta << " |R|"
              << (taken == Step::on_trial ? " (full step on trial)" : "")
              << std::endl;
        // A trial that fails fails the load step: its shortened steps
        // would make slow progress (the continuation halves the load).
        if (taken == Step::accepted &&
            watchdog.judge(r.l2_norm()) == NewtonWatchdog::Verdict::restore)
          {
            result.failure = trial_failure(watchdog);
            return false;
          }
      }
  }

  std::string
  DirectInverse::trial_failure(const NewtonWatchdog &watchdog)
  {
    return "a full step taken on trial left |R| above its target after " +
           std::to_string(watchdog.trial_steps()) + " more steps";
  }

  DirectInverse::Direction
  DirectInverse::newton_direction(const VectorType &w,
                                  const VectorType &r,
                                  const double      eta)
  {
    VectorType delta = forward.discretization().zero_vector(), minus_r = r;
    minus_r *= -1;
    // The products difference the residual with the step's three-field
    // pressures (from the assembly of r, the last one), the preconditioner
    // is their tangent; the right-hand side is the condensed residual.
    VectorType base = r;
    pressures.begin_step();
    if (pressures.enabled())
      residual(w, base);
    forward.set_state(d, w, load);
    forward.prepare_consistent_tangent();
    ++result.factorisations;
    // Right-preconditioned by the forward tangent dR/dd (dR/dw = -dR/dd
    // for small strains, and R's sign makes the product with dR/dw near
    // identity): factorised, or an inner CG + AMG solve. If GMRES stops at
    // max_gmres_steps, the line search judges the best iterate so far.
    VectorType                trial    = forward.discretization().zero_vector();
    unsigned int              products = 0;
    const FlexibleGmresResult gmres =
      FlexibleGmres(max_gmres_steps)
        .solve(
          [&](VectorType &dst, const VectorType &src) {
            set_progress_phase("direct inverse, Newton step " +
                               std::to_string(result.newton_steps + 1) +
                               ": Jacobian product " +
                               std::to_string(++products) + " (GMRES)");
            jacobian_product(w, base, src, trial, dst);
          },
          [&](VectorType &dst, const VectorType &src) {
            forward.solve_with_tangent(dst, src, inner_tolerance);
          },
          delta,
          minus_r,
          eta * r.l2_norm());
    if (pressures.enabled() && delta.linfty_norm() > 0)
      {
        const double e = difference_step(delta);
        trial          = w;
        trial.add(e, delta);
        residual(trial, base);
        pressures.record_direction(e);
      }
    pressures.end_products();
    return {delta,
            gmres.iterations,
            gmres.residual <= eta * r.l2_norm() ||
              gmres.iterations < max_gmres_steps};
  }

  DirectInverse::Step
  DirectInverse::line_search(VectorType       &w,
                             VectorType       &r,
                             const VectorType &delta,
                             NewtonWatchdog   &watchdog)
  {
    // Backtracking on |R|, never through an inverted rest cell.
    const double r_norm  = r.l2_norm();
    VectorType   w_trial = w, r_trial = forward.discretization().zero_vector();
    double       alpha = 1;
    for (unsigned int h = 0; h <= max_halvings; ++h, alpha /= 2)
      {
        w_trial = w;
        w_trial.add(alpha, delta);
        if (!residual(w_trial, r_trial))
          continue;
        const double trial_norm = r_trial.l2_norm();
        // While a trial is on, the three-field steps are full steps (the
        // condensed residual weighs their second-order change of volume
        // by K, which the next step removes): the watchdog judges them.
        const bool relaxed = h == 0 && pressures.enabled() &&
                             watchdog.on_trial() && std::isfinite(trial_norm);
        const bool decreases =
          relaxed || trial_norm <= (1 - armijo * alpha) * r_norm;
        // A full step above the target may still lead to the solution:
        // the watchdog takes it on trial (never one with an inverted cell).
        const bool let_through = !decreases && h == 0 &&
                                 std::isfinite(trial_norm) &&
                                 watchdog.may_let_through();
        if (let_through)
          watchdog.let_through(w, (1 - armijo) * r_norm);
        if (decreases || let_through)
          {
            w = w_trial;
            r = r_trial;
            pressures.accept(alpha);
            return let_through ? Step::on_trial : Step::accepted;
          }
      }
    result.failure = "the line search could not reduce the residual";
    pressures.forget();
    return Step::failed;
  }
} // namespace RestShape
