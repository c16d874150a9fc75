#include <restshape/base/input_error.h>
#include <restshape/base/units.h>
#include <restshape/contact/admissible_target.h>
#include <restshape/contact/contact_report.h>
#include <restshape/forward/forward_results.h>
#include <restshape/inverse/inverse_problem.h>
#include <restshape/inverse/load_path.h>
#include <restshape/inverse/stopping_rules.h>

#include <cstdio>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// A load path that strains the fixed labels' faces by more than this
    /// (force / (area E)) holds no rest shape: the co-rotational law
    /// inverts a cell compressed by a strain of 1.
    constexpr double max_support_strain = 1;
  } // namespace

  InverseProblem::InverseProblem(const InverseParameters &parameters,
                                 ForwardProblem          &forward,
                                 ContactProblem          *contact,
                                 OutputWriter            *output,
                                 TimerOutput             &timer,
                                 ConditionalOStream      &pcout,
                                 const Timer             &wall_timer)
    : parameters(parameters)
    , forward(forward)
    , contact(contact)
    , output(output)
    , timer(timer)
    , pcout(pcout)
    , wall_timer(wall_timer)
  {}

  std::pair<double, double>
  InverseProblem::target_errors() const
  {
    VectorType e = forward.discretization().owned_copy(forward.displacement());
    e -= target_shift;
    return nodal_norms(forward.discretization(), e);
  }

  bool
  InverseProblem::converged(const std::pair<double, double> &errors) const
  {
    // An equilibrium with nodes beyond the obstacle (free since its solve
    // started with them there) does not meet the contact conditions: not
    // a rest shape, however small the error.
    const unsigned int outside =
      contact != nullptr ? ContactReport(*contact).n_outside() : 0;
    if (outside > 0)
      {
        pcout << "  " << outside
              << " contact nodes lie beyond the obstacle: not converged"
              << std::endl;
        return false;
      }
    return measure(errors) <= parameters.tolerance &&
           errors.second <= parameters.max_tolerance;
  }

  void
  InverseProblem::set_admissible_target(InverseResult &result)
  {
    target_shift = forward.discretization().zero_vector();
    if (contact == nullptr)
      return;
    target_shift = AdmissibleTarget(*contact).shift();
    set_unreachable(result);
    if (result.unreachable_nodes > 0)
      pcout << "Target: " << result.unreachable_nodes
            << " contact nodes of the image lie beyond the obstacle (by up to "
            << mm_text(result.unreachable_max) << ", mean "
            << mm_text(result.unreachable_mean)
            << "); the iteration aims at the admissible target, those nodes "
               "projected onto it"
            << std::endl;
    if (relax_admissible_target(result))
      set_unreachable(result);
  }

  void
  InverseProblem::set_unreachable(InverseResult &result) const
  {
    const auto unreachable =
      nodal_norms_above(forward.discretization(), target_shift, 0.);
    result.unreachable_nodes = unreachable.n;
    result.unreachable_max   = unreachable.max;
    result.unreachable_mean  = unreachable.mean;
  }

  bool
  InverseProblem::relax_admissible_target(InverseResult &result)
  {
    unsigned int n_inverted = 0;
    if (target_shift.linfty_norm() == 0 ||
        rest_shape_is_valid(forward.discretization(), target_shift, n_inverted))
      return false;
    const TargetRelaxation       relaxation(forward.discretization(),
                                      contact->surface());
    const TargetRelaxationResult r = relaxation.relax(target_shift);
    result.relaxation              = r;
    pcout << "Target: the projection onto the obstacle inverts "
          << r.inverted_before << " cells; " << r.moved_nodes
          << " nodes near them follow their neighbours (" << r.sweeps
          << " smoothing sweeps, moved by up to " << mm_text(r.largest_change)
          << "); " << r.inverted_after << " cells still inverted, "
          << r.below_threshold
          << " below det(dx_target/dX) = " << TargetRelaxation::minimum_jacobian
          << std::endl;
    return true;
  }

  double
  InverseProblem::measure(const std::pair<double, double> &errors) const
  {
    return parameters.measure == InverseParameters::Measure::mean ?
             errors.first :
             errors.second;
  }

  const std::vector<InverseIterationRecord> &
  InverseProblem::records() const
  {
    return history;
  }

  void
  InverseProblem::record(const unsigned int     iteration,
                         const SolveStatistics &stats,
                         const bool             anderson)
  {
    const auto errors = target_errors();
    const auto image =
      nodal_norms(forward.discretization(), forward.displacement());
    history.push_back(
      {iteration,
       errors.first,
       errors.second,
       image.first,
       image.second,
       stats.newton_iterations,
       contact != nullptr ? ContactReport(*contact).n_active() : 0,
       wall_timer.wall_time(),
       anderson});
    std::string contact_text;
    if (contact != nullptr)
      {
        contact_text = ", " +
                       std::to_string(history.back().active_contact_nodes) +
                       " contact nodes";
        const auto [n_fixed, distance] =
          ContactReport(*contact).fixed_plane_nodes();
        if (n_fixed > 0)
          contact_text += ", " + std::to_string(n_fixed) +
                          " on fixed planes, up to " + mm_text(distance) +
                          " off the obstacle";
      }
    pcout << "Inverse iteration " << iteration << ": mean error "
          << mm_text(errors.first) << ", max " << mm_text(errors.second) << " ("
          << stats.newton_iterations << " Newton iterations"
          << (anderson ? ", Anderson step" : "") << contact_text << ")"
          << std::endl;
  }

  void
  InverseProblem::write_output(const unsigned int            step,
                               const std::vector<CellField> &cells)
  {
    if (output == nullptr)
      return;
    last_step = step;
    TimerOutput::Scope scope(timer, "Output");
    // Nodal vectors: the error X_target - X_eq = -d, and the three shapes.
    VectorType error  = target_shift,
               target = forward.discretization().zero_vector();
    error -= forward.discretization().owned_copy(forward.displacement());
    for (const Node &node : forward.discretization().owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        target[node.dofs[c]] = node.position[c];
    target.compress(VectorOperation::insert);
    VectorType rest = target, equilibrium = target;
    rest += forward.discretization().owned_copy(forward.rest_displacement());
    equilibrium += forward.discretization().owned_copy(forward.displacement());

    const std::string       unit   = output->length_unit_name;
    const double            scale  = output->length_scale();
    std::vector<NodalField> fields = {
      {&error, {"error_" + unit}, scale, "error_magnitude_" + unit},
      {&target, {"target_position_" + unit}, scale, ""},
      {&rest, {"rest_position_" + unit}, scale, ""},
      {&equilibrium, {"equilibrium_position_" + unit}, scale, ""},
      {&target_shift,
       {"unreachable_target_" + unit},
       scale,
       "unreachable_target_magnitude_" + unit}};
    VectorType contact_fields;
    if (contact != nullptr)
      {
        contact_fields =
          ContactReport(*contact).nodal_fields(forward.raw_residual(), scale);
        fields.push_back(
          {&contact_fields,
           {"contact_active", "contact_gap_" + unit, "contact_pressure_Pa"},
           1.,
           ""});
      }
    // The record's time is its step: it increases over the iterations of
    // every refinement cycle (iterations.csv maps steps to iterations).
    output->write_fields(forward, step, step, fields, cells);
  }

  void
  InverseProblem::rewrite_final_output(const std::vector<CellField> &cells)
  {
    if (last_step != static_cast<unsigned int>(-1))
      write_output(last_step, cells);
  }

  InverseResult
  InverseProblem::finish(InverseResult &result, const std::string &reason) const
  {
    result.reason     = reason;
    const auto e      = target_errors();
    result.mean_error = e.first;
    result.max_error  = e.second;
    const auto image =
      nodal_norms(forward.discretization(), forward.displacement());
    result.mean_image_error = image.first;
    result.max_image_error  = image.second;
    if (!reason.empty())
      pcout << "Inverse iteration stopped: " << reason << std::endl;
    return result;
  }

  SolveStatistics
  InverseProblem::first_solve(const VectorType &initial_rest,
                              const VectorType *guess,
                              const LoadState  &load,
                              InverseResult    &result,
                              VectorType       &start)
  {
    // Where the image crosses the obstacle, the first rest shape is the
    // admissible target (else the nodes beyond it start free, on the wrong
    // side, and may be all that would hold the body). run() has checked
    // that it inverts no cell.
    start                      = initial_rest;
    const bool from_admissible = guess == nullptr &&
                                 initial_rest.linfty_norm() == 0 &&
                                 target_shift.linfty_norm() > 0;
    SolveStatistics stats;
    if (from_admissible)
      {
        start = target_shift;
        forward.set_state(start, start, LoadState());
        contact->reset();
        stats = forward.solve(load, start);
        if (!stats.converged)
          {
            pcout << "  The forward solve from the admissible target failed ("
                  << stats.failure << "); starting from the image instead"
                  << std::endl;
            result.forward_solves += 1;
            result.newton_iterations += stats.newton_iterations;
            start = initial_rest;
          }
      }
    if (!from_admissible || !stats.converged)
      stats = forward.solve_from(guess, load, initial_rest);
    ++result.forward_solves;
    result.newton_iterations += stats.newton_iterations;
    return stats;
  }

  bool
  InverseProblem::direct_inverse(const VectorType &initial_rest,
                                 const LoadState  &load,
                                 InverseResult    &result,
                                 VectorType       &rest)
  {
    // Where the image crosses the obstacle, contact acts at the target,
    // which the direct inverse does not model: it then solves for the
    // image without contact, and the fixed point takes its rest shape on
    // to the admissible target.
    const bool        carries = result.carried.share > 0;
    const std::string unheld  = directions_only_contact_holds();
    if (!carries && !unheld.empty())
      {
        result.direct         = DirectInverseResult();
        result.direct.failure = "skipped: no fixed label or elastic support "
                                "holds the body in " +
                                unheld +
                                " (only the obstacle does, which the direct "
                                "inverse does not model: its tangent is "
                                "singular there)";
        pcout << "  Direct inverse: " << result.direct.failure
              << "; the fixed point starts from the target" << std::endl;
        return false;
      }
    if (target_shift.linfty_norm() > 0 && !carries)
      pcout << "  Direct inverse: at the image, without contact (the fixed "
               "point then aims at the admissible target)"
            << std::endl;
    rest = forward.discretization().owned_copy(initial_rest);
    // Aiming at the admissible target, start stress-free there.
    if (carries && rest.linfty_norm() == 0)
      rest = target_shift;
    if (contact != nullptr)
      contact->reset(); // contact is not part of the direct inverse
    const VectorType from_target =
      carries ? target_shift : forward.discretization().zero_vector();
    VectorType given_shift = rest; // a previous cycle's, a file's
    given_shift -= from_target;
    const bool given = given_shift.linfty_norm() > 0;
    result.direct    = solve_direct_inverse(load, result, rest);
    if (!result.direct.converged && given)
      {
        // An interpolated rest shape of a nearly incompressible body
        // carries a volume error times the bulk modulus: the target,
        // stress-free, is the better start (the column at nu = 0.4999
        // refined once: 5 Newton steps from there, a failure after 22
        // from the previous cycle's rest shape).
        const DirectInverseResult first = result.direct;
        pcout << "  Direct inverse: failed from the given rest shape ("
              << first.failure << ") in " << first.newton_steps
              << " Newton steps; again from the target" << std::endl;
        rest          = from_target;
        result.direct = solve_direct_inverse(load, result, rest);
        result.direct.newton_steps += first.newton_steps;
        result.direct.factorisations += first.factorisations;
        result.direct.jacobian_products += first.jacobian_products;
      }
    const DirectInverseResult &r = result.direct;
    pcout << "  Direct inverse: "
          << (r.converged ? "converged" : "failed (" + r.failure + ")")
          << " in " << r.newton_steps << " Newton steps (" << r.factorisations
          << " factorisations, " << r.jacobian_products << " Jacobian products)"
          << (r.converged ? "; the fixed point checks it" :
                            "; the fixed point starts from the target")
          << std::endl;
    return r.converged;
  }

  DirectInverseResult
  InverseProblem::solve_direct_inverse(const LoadState     &load,
                                       const InverseResult &result,
                                       VectorType          &rest)
  {
    TimerOutput::Scope scope(timer, "Direct inverse");
    DirectInverse      inverse(forward, pcout);
    if (result.carried.share > 0)
      inverse.set_target(target_shift, result.carried.forces);
    return inverse.solve(load, rest);
  }

  std::string
  InverseProblem::directions_only_contact_holds() const
  {
    if (contact == nullptr || forward.loads().has_support())
      return "";
    const std::array<bool, 3> held =
      forward.discretization().fixed_components();
    std::string unheld;
    for (unsigned int c = 0; c < 3; ++c)
      if (!held[c])
        unheld += std::string(unheld.empty() ? "" : ", ") + "xyz"[c];
    return unheld;
  }

  std::string
  InverseProblem::next_rest_shape(const VectorType    &w,
                                  const VectorType    &f,
                                  AndersonAccelerator &anderson,
                                  const bool           accelerate,
                                  const unsigned int   iteration,
                                  const double         last_error,
                                  VectorType          &candidate,
                                  bool                &accelerated) const
  {
    VectorType plain = w;
    plain += f;
    candidate   = plain;
    accelerated = false;
    if (accelerate)
      {
        candidate   = anderson.next(w, f);
        accelerated = anderson.columns_used() > 0;
      }
    // Never a rest shape with an inverted or degenerate cell.
    unsigned int n_bad = 0;
    std::string  where;
    if (rest_shape_is_valid(forward.discretization(), candidate, n_bad))
      return "";
    if (accelerated)
      {
        pcout << "  Anderson step would invert " << n_bad
              << " cells: plain update" << std::endl;
        anderson.reset();
        anderson.next(w, f);
        candidate   = plain;
        accelerated = false;
      }
    constexpr double shortest = 1. / 64;
    for (double beta = 0.5; !rest_shape_is_valid(
           forward.discretization(), candidate, n_bad, &where);
         beta /= 2)
      {
        if (beta < shortest)
          return "every rest-shape update, even shortened 64 times, would "
                 "invert " +
                 std::to_string(n_bad) + " cells, e.g. " + where +
                 " (iteration " + std::to_string(iteration) + ", error " +
                 mm_text(last_error) + ")";
        candidate = w;
        candidate.add(beta, f);
        pcout << "  The update would invert " << n_bad
              << " cells: shortened to " << beta << std::endl;
      }
    return "";
  }

  InverseResult
  InverseProblem::run(const VectorType  &initial_rest,
                      const unsigned int first_step,
                      const VectorType  *guess)
  {
    InverseResult result;
    history.clear();
    // The fixed point's forward solves follow the one-sided rule: a rest
    // shape may lie beyond the obstacle. Forward simulations after the
    // inverse (stability, comparisons) do not.
    struct OneSided
    {
      ContactProblem *contact;
      OneSided(ContactProblem *c)
        : contact(c)
      {
        if (contact != nullptr)
          contact->set_one_sided(true);
      }
      ~OneSided()
      {
        if (contact != nullptr)
          contact->set_one_sided(false);
      }
    } one_sided(contact);
    const LoadState load = forward.loads().scene_load();
    set_admissible_target(result);
    // An equilibrium x at the admissible target has det(dx/dX_mesh) =
    // det F det(dX_rest/dX_mesh) > 0 for any valid rest shape: a target
    // that inverts a cell is reached by none. (The target was checked, and
    // relaxed where the projection inverted cells, by set_admissible_target.)
    const TargetRelaxationResult &relaxed = result.relaxation;
    if (relaxed.inverted_after > 0)
      return finish(result,
                    "no rest shape exists: the admissible target inverts " +
                      std::to_string(relaxed.inverted_after) + " cells, e.g. " +
                      relaxed.where +
                      " (the obstacle cuts deeper into the image than these "
                      "cells are thick: projected onto it and smoothed, their "
                      "surface nodes still pass their inner ones; move the "
                      "obstacle out or refine the mesh near it)");
    // Whether anything can hold the target: a load that only the fixed
    // labels can carry, and that strains them beyond what the law carries,
    // is the likely cause when the direct inverse fails (the fixed point
    // would then only wander: on a brain held by a stalk, 900 Newton steps
    // in 33 minutes).
    const LoadPath path   = assess_load_path(forward, contact, load);
    const bool overloaded = path.assessed && path.strain > max_support_strain;
    if (path.assessed)
      pcout << "Load path at the target: " << path.text() << std::endl;
    const auto load_path_failure = [&](const std::string &what) {
      return what +
             "; the load path at the target explains it: " + path.text() +
             ", more than the tissue can carry (a strain of " +
             number_text(max_support_strain) + " inverts cells); expected " +
             LoadPath::remedy();
    };
    const bool direct = parameters.method == InverseParameters::Method::direct;
    if (overloaded && !direct)
      return finish(result,
                    load_path_failure("no rest shape sought: the fixed point "
                                      "would not settle"));
    // Method = direct: the fixed point starts from the direct inverse's
    // rest shape, Newton from the target at the full load.
    VectorType        direct_rest, target_guess;
    const VectorType *rest = &initial_rest;
    if (direct && parameters.skull_load_share > 0 && contact != nullptr)
      {
        TimerOutput::Scope scope(timer, "Reference contact solve");
        result.carried = carried_load(
          forward, *contact, target_shift, load, parameters.skull_load_share);
        pcout << result.carried.text() << std::endl;
        if (!result.carried.converged)
          return finish(result,
                        "no load-carrying rest shape: the reference contact "
                        "solve did not converge (" +
                          result.carried.failure + ")");
      }
    if (direct)
      {
        if (direct_inverse(initial_rest, load, result, direct_rest))
          {
            rest = &direct_rest;
            // Newton from the target (admissible, where it carries).
            target_guess = result.carried.share > 0 ?
                             target_shift :
                             forward.discretization().zero_vector();
            guess        = &target_guess;
          }
        else if (result.carried.share > 0)
          return finish(result,
                        "no load-carrying rest shape found: the direct "
                        "inverse failed (" +
                          result.direct.failure + ")");
        else if (overloaded)
          return finish(result,
                        load_path_failure("no rest shape found: the direct "
                                          "inverse failed (" +
                                          result.direct.failure + ")"));
      }
    VectorType      start;
    SolveStatistics stats = first_solve(*rest, guess, load, result, start);
    if (!stats.converged)
      return finish(result,
                    "the forward solve from the initial rest shape did not "
                    "converge: " +
                      stats.failure);
    record(0, stats, false);
    write_output(first_step);

    const double  initial = measure(target_errors());
    StoppingRules stopping(initial, parameters.tolerance);
    if (converged(target_errors()))
      {
        result.converged = true;
        return finish(result, "");
      }

    const bool accelerate =
      parameters.acceleration == InverseParameters::Acceleration::anderson;
    AndersonAccelerator anderson(parameters.anderson_depth);
    VectorType          w = start, d = forward.discretization().zero_vector();
    d                = forward.displacement(); // owned layout
    bool force_plain = false;
    while (result.iterations < parameters.max_iterations)
      {
        // The fixed point: e = X_target - X_eq = t - d (t: the admissible
        // target's shift); plain update w + e.
        VectorType f = target_shift;
        f -= d;
        if (accelerate && force_plain)
          anderson.reset();
        force_plain = false;
        VectorType        candidate;
        bool              accelerated = false;
        const std::string impossible  = next_rest_shape(w,
                                                       f,
                                                       anderson,
                                                       accelerate,
                                                       result.iterations + 1,
                                                       stopping.last(),
                                                       candidate,
                                                       accelerated);
        if (!impossible.empty())
          return finish(result, impossible);

        // Forward solve from the last equilibrium, the rest shape moving
        // from w to the candidate.
        const auto contact_state =
          contact != nullptr ? contact->state() : ContactProblem::State();
        stats = forward.solve(load, candidate);
        ++result.forward_solves;
        result.newton_iterations += stats.newton_iterations;
        const auto   errors = target_errors();
        const double error  = measure(errors);
        // A plain update whose forward solve failed: the forward solve has
        // already tried ever smaller fractions of it (its load-step
        // halvings), so shortening it here would only repeat that work.
        // Either it reached equilibrium part of the way, and that shorter
        // update is the new iterate, or the iteration stops at once.
        bool partial = false;
        if (!stats.converged && !accelerated)
          {
            if (!(stats.fraction > 0))
              return finish(result,
                            "the forward solve of iteration " +
                              std::to_string(result.iterations + 1) +
                              " did not converge even for the smallest "
                              "fraction of the update: " +
                              stats.failure);
            pcout << "  The forward solve reached equilibrium at "
                  << stats.fraction
                  << " of the update: that shorter update is taken"
                  << std::endl;
            VectorType update = candidate;
            update -= w;
            candidate = w;
            candidate.add(stats.fraction, update);
            partial     = true;
            force_plain = true;
          }
        else if (!stats.converged || (accelerated && error > stopping.last()))
          {
            // Back to the last iterate; the plain update follows.
            forward.set_state(d, w, load);
            if (contact != nullptr)
              contact->set_state(contact_state);
            pcout << "  Anderson step rejected ("
                  << (stats.converged ?
                        "error " + mm_text(error) + " > " +
                          mm_text(stopping.last()) :
                        "forward solve failed: " + stats.failure)
                  << "): plain update" << std::endl;
            ++result.rejected_steps;
            force_plain = true;
            continue;
          }

        w = candidate;
        d = forward.displacement();
        ++result.iterations;
        result.partial_updates += partial;
        record(result.iterations, stats, accelerated);
        write_output(first_step + result.iterations);

        if (converged(errors))
          {
            result.converged = true;
            return finish(result, "");
          }
        const std::string reason = stopping.check(
          result.iterations, error, partial, stats.fraction, stats.failure);
        if (!reason.empty())
          return finish(result, reason);
      }
    return finish(result,
                  "not converged after " +
                    std::to_string(parameters.max_iterations) +
                    " iterations (error " + mm_text(stopping.last()) +
                    ", tolerance " + mm_text(parameters.tolerance) + ")");
  }
} // namespace RestShape
