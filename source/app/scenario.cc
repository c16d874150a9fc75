// Scenario: the changed load, the two solves and the shift of each tissue.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <restshape/app/scenario.h>
#include <restshape/base/input_error.h>
#include <restshape/base/mpi_reductions.h>
#include <restshape/base/progress.h>
#include <restshape/base/units.h>
#include <restshape/base/vector_text.h>
#include <restshape/contact/contact_report.h>
#include <restshape/fem/nodal_norms.h>
#include <restshape/postprocess/postprocessor.h>
#include <restshape/postprocess/scenario_report.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    constexpr double ml_per_m3 = 1e6;
  } // namespace

  void
  check_craniotomy(const Parameters         &parameters,
                   const ScenarioParameters &p,
                   const LabelledMesh       &mesh,
                   const MPI_Comm            comm)
  {
    const Region &opening = p.change.opening;
    if (!opening.defined())
      return;
    // Surface faces of the body (mesh geometry) whose centre lies inside.
    unsigned int faces = 0;
    for (const auto &cell : mesh.triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          faces += mesh.at_surface(*cell, f) &&
                   opening.contains(cell->face(f)->center());
    if (Utilities::MPI::sum(faces, comm) == 0)
      throw InputError(
        "",
        p.section() + "/Craniotomy",
        "the " +
          opening.text(parameters.mesh.length_unit,
                       parameters.mesh.length_unit_name) +
          " contains no face of the body's surface: it opens nothing; "
          "expected a region that cuts the skull where the brain's surface "
          "lies");
  }

  void
  check_fluid_level(const Parameters         &parameters,
                    const ScenarioParameters &p,
                    const LabelledMesh       &mesh,
                    const MPI_Comm            comm)
  {
    const Tensor<1, 3> g =
      p.change.rotation * parameters.forward.environment.gravity;
    const Point<3> &level = p.change.fluid_level;
    if (g.norm() == 0)
      throw InputError("",
                       p.section() + "/Fluid level",
                       "without gravity no level is defined; expected "
                       "Loads/Gravity != 0");
    // Height of the body's highest vertex above the level (m).
    double top = -std::numeric_limits<double>::max();
    for (const Point<3> &v : mesh.triangulation().get_vertices())
      top = std::max(top, -(g * (v - level)) / g.norm());
    top = Utilities::MPI::max(top, comm);
    if (top <= 0)
      throw InputError(
        "",
        p.section() + "/Fluid level",
        "the level lies " + number_text(-top / parameters.mesh.length_unit) +
          " " + parameters.mesh.length_unit_name +
          " above the body's highest point (against gravity): nothing is "
          "drained; expected a point below the top of the body");
  }

  void
  check_scenario(const Parameters   &parameters,
                 const LabelledMesh &mesh,
                 const MPI_Comm      comm)
  {
    for (const ScenarioParameters &p : parameters.scenarios)
      {
        check_craniotomy(parameters, p, mesh, comm);
        if (p.change.has_fluid_level)
          check_fluid_level(parameters, p, mesh, comm);
      }
  }

  std::map<Label, TissueShift>
  tissue_shifts(const ForwardProblem &forward, const VectorType &u_owned)
  {
    const VectorType    u = forward.discretization().ghosted_copy(u_owned);
    const unsigned int  p = forward.discretization().fe().degree;
    const Quadrature<3> quadrature =
      forward.discretization().mesh().is_simplex() ?
        Quadrature<3>(QGaussSimplex<3>(p + 1)) :
        Quadrature<3>(QGauss<3>(p + 1));
    FEValues<3>                      fv(forward.discretization().mapping(),
                   forward.discretization().fe(),
                   quadrature,
                   update_values | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, 3>>        values(quadrature.size());
    std::map<types::global_dof_index, const Node *> node_of;
    for (const Node &node : forward.discretization().relevant_nodes())
      node_of[node.dofs[0]] = &node;
    std::vector<types::global_dof_index> dofs(
      forward.discretization().fe().n_dofs_per_cell());

    std::map<Label, TissueShift> shifts;
    for (const Label label : forward.discretization().mesh().labels())
      shifts[label];
    for (const auto &cell :
         forward.discretization().dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          TissueShift &t = shifts[cell->material_id()];
          fv.reinit(cell);
          fv[displacement].get_function_values(u, values);
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              t.volume += fv.JxW(q);
              t.centroid += values[q] * fv.JxW(q);
            }
          cell->get_dof_indices(dofs);
          for (const auto dof : dofs)
            if (const auto it = node_of.find(dof); it != node_of.end())
              {
                const Node  &node = *it->second;
                Tensor<1, 3> v;
                for (unsigned int c = 0; c < 3; ++c)
                  v[c] = u[node.dofs[c]];
                if (v.norm() > t.max_shift)
                  {
                    t.max_shift = v.norm();
                    t.max_where = node.position;
                  }
              }
        }
    const MPI_Comm comm =
      forward.discretization().dof_handler().get_communicator();
    for (auto &[label, t] : shifts)
      {
        t.volume = Utilities::MPI::sum(t.volume, comm);
        for (unsigned int c = 0; c < 3; ++c)
          t.centroid[c] = Utilities::MPI::sum(t.centroid[c], comm);
        if (t.volume > 0)
          t.centroid /= t.volume;
        std::tie(t.max_shift, t.max_where) =
          largest_with_place(t.max_shift, t.max_where, comm);
      }
    return shifts;
  }

  Scenario::Scenario(const Parameters                 &parameters,
                     const ScenarioParameters         &scenario,
                     ForwardProblem                   &forward,
                     ContactProblem                   *contact,
                     OutputWriter                     &output,
                     Summary                          &summary,
                     const dealii::ConditionalOStream &pcout)
    : parameters(parameters)
    , scenario(scenario)
    , forward(forward)
    , contact(contact)
    , output(output)
    , summary(summary)
    , pcout(pcout)
  {}

  std::string
  Scenario::description(const LoadState &scene, const LoadState &changed) const
  {
    const ScenarioChange &p = scenario.change;
    std::string           text;
    const auto            add = [&](const std::string &part) {
      if (!part.empty())
        text += (text.empty() ? "" : "; ") + part;
    };
    if (p.turned)
      add("gravity " + vector_text(parameters.forward.environment.gravity) +
          " turned by " + vector_text(p.rotation_degrees) + " degrees to " +
          vector_text(p.rotation * parameters.forward.environment.gravity) +
          " m/s^2");
    if (p.has_fluid_level)
      add("fluid drained above " +
          vector_text(p.fluid_level, parameters.mesh.length_unit) + " " +
          parameters.mesh.length_unit_name);
    if (p.opening.defined())
      add("craniotomy: " +
          p.opening.text(parameters.mesh.length_unit,
                         parameters.mesh.length_unit_name) +
          " (" + std::to_string(opened_nodes) +
          " surface nodes freed from the skull, " +
          std::to_string(opened_faces) + " pressure faces at 0 Pa)");
    add(forward.loads().change_text(scene, changed));
    for (const auto &[name, factor] : scenario.scale)
      add(name + " scaled by " + number_text(factor));
    return text.empty() ? "no change" : text;
  }

  const std::string &
  Scenario::failure() const
  {
    return failure_text;
  }

  bool
  Scenario::failed(const SolveStatistics &s, const std::string &model)
  {
    failure_text = model + " model: " + s.failure;
    record_scenario_failure(summary, scenario.output_name(), failure_text);
    pcout << "  " << scenario.section() << " did not converge (" << failure_text
          << "); the next scenario starts from the equilibrium again"
          << std::endl;
    return false;
  }

  SolveStatistics
  Scenario::solve(const LoadState &load, const VectorType &rest)
  {
    try
      {
        return forward.solve(load, rest);
      }
    catch (const SolverFailure &e)
      {
        SolveStatistics s;
        s.converged = false;
        s.failure   = e.what();
        return s;
      }
  }

  bool
  Scenario::run()
  {
    // The pre-stressed model's equilibrium: where both models start.
    const VectorType d_eq =
      forward.discretization().owned_copy(forward.displacement());
    const VectorType w_rest =
      forward.discretization().owned_copy(forward.rest_displacement());
    const LoadState scene = forward.load();
    const LoadState changed =
      forward.loads().changed_load(scenario.change, scene, scenario.scale);
    ContactProblem::State equilibrium_set;
    if (contact != nullptr)
      equilibrium_set = contact->state();
    const Region &opening = scenario.change.opening;
    if (opening.defined())
      {
        opened_faces = forward.loads().open(opening);
        if (contact != nullptr)
          opened_nodes = contact->remove_contact(opening);
        record_scenario_opening(summary,
                                scenario.output_name(),
                                opened_nodes,
                                opened_faces);
      }
    ContactProblem::State start_set;
    if (contact != nullptr)
      start_set = contact->state();
    pcout << scenario.section() << ": " << description(scene, changed)
          << std::endl;

    pcout << "  pre-stressed model: the scene's loads -> the changed loads"
          << std::endl;
    set_progress_phase(scenario.section() + ", pre-stressed model");
    const LoadState change = difference(changed, scene);
    // Back at the equilibrium, the skull closed, for the next scenario.
    const auto back_to_equilibrium = [&]() {
      forward.loads().open(Region());
      if (contact != nullptr)
        {
          contact->close_openings();
          contact->set_state(equilibrium_set);
        }
      forward.set_state(d_eq, w_rest, scene);
    };
    const SolveStatistics s1 = solve_pre_stressed(changed, change, w_rest);
    if (!s1.converged)
      {
        back_to_equilibrium();
        return failed(s1, "pre-stressed");
      }
    const VectorType d1 =
      forward.discretization().owned_copy(forward.displacement());
    VectorType u1 = d1;
    u1 -= d_eq;
    // What carries the changed load, at the pre-stressed model's end state
    // (its contact set and normals; the stress-free solve changes them).
    const SolveReductions r = compute_reductions(
      forward,
      contact,
      u1,
      parameters.inverse.enabled,
      forward.discretization().dof_handler().get_communicator());
    record_scenario_forces(summary, scenario.output_name(), r);
    VectorType contact_fields;
    if (contact != nullptr)
      contact_fields =
        ContactReport(*contact).nodal_fields(forward.raw_residual(),
                                             output.length_scale());
    ContactProblem::State end_set;
    if (contact != nullptr)
      end_set = contact->state();

    pcout << "  stress-free model (rest shape = the pre-stressed equilibrium, "
             "the same contact set): the change alone"
          << std::endl;
    set_progress_phase(scenario.section() + ", stress-free model");
    VectorType            u2 = forward.discretization().zero_vector();
    const SolveStatistics s2 = solve_stress_free(change, d_eq, start_set, u2);
    if (!s2.converged)
      {
        back_to_equilibrium();
        return failed(s2, "stress-free");
      }

    // The pre-stressed model's end state is the one written.
    forward.set_state(d1, w_rest, changed);
    if (contact != nullptr)
      contact->set_state(end_set);
    record_scenario_newton(summary, scenario.output_name(), s1, s2);
    report(u1, u2, contact_fields);
    record_scenario_success(summary, scenario.output_name());
    back_to_equilibrium();
    return true;
  }

  SolveStatistics
  Scenario::solve_pre_stressed(const LoadState  &changed,
                               const LoadState  &change,
                               const VectorType &w_rest)
  {
    SolveStatistics s;
    if (change.empty() && !scenario.change.opening.defined())
      {
        // Nothing changes: the equilibrium stays, exactly (a contact solve
        // from it could move it within the gap tolerance: the nodes it
        // released for pulling are activated again).
        // Its residual (what the reductions and contact forces read) is
        // assembled anew: an earlier scenario's solve left its own.
        s.converged = forward.evaluate();
        pcout << "      no change of load: the pre-stressed model stays"
              << std::endl;
        return s;
      }
    return solve(changed, w_rest);
  }

  SolveStatistics
  Scenario::solve_stress_free(const LoadState             &change,
                              const VectorType            &d_eq,
                              const ContactProblem::State &start_set,
                              VectorType                  &shift)
  {
    SolveStatistics s;
    shift = 0;
    if (change.empty())
      {
        // Stress-free under no load, it stays where it is: an exact
        // solution, which a solve would only blur with its contact
        // tolerances (nodes within the gap tolerance pushed onto the
        // skull, against a load of 0 N as the reference).
        s.converged = true;
        pcout << "      no change of load: the stress-free model stays"
              << std::endl;
        return s;
      }
    forward.set_state(d_eq, d_eq, LoadState());
    if (contact != nullptr)
      contact->set_state(start_set);
    s = solve(change, d_eq);
    if (!s.converged)
      return s;
    shift = forward.discretization().owned_copy(forward.displacement());
    shift -= d_eq;
    return s;
  }

  void
  Scenario::report(const VectorType &prestressed,
                   const VectorType &stress_free,
                   const VectorType &contact_fields)
  {
    const auto        a     = tissue_shifts(forward, prestressed);
    const auto        b     = tissue_shifts(forward, stress_free);
    const LabelNames &names = forward.discretization().mesh().label_names();
    // Ratios of shifts below a nanometre are ratios of round-off: 0.
    constexpr double least_shift = 1e-9; // m
    const auto       ratio       = [](const double x, const double y) {
      return x > least_shift ? y / x : 0.;
    };
    output.write_text(scenario.output_name() + ".csv", [&](std::ostream &out) {
      out << std::setprecision(6)
          << "tissue,label,volume_ml,"
             "prestressed_centroid_x_mm,prestressed_centroid_y_mm,"
             "prestressed_centroid_z_mm,prestressed_centroid_mm,"
             "stress_free_centroid_x_mm,stress_free_centroid_y_mm,"
             "stress_free_centroid_z_mm,stress_free_centroid_mm,"
             "prestressed_max_mm,stress_free_max_mm,"
             "ratio_centroid,ratio_max\n";
      for (const auto &[label, t] : a)
        {
          const TissueShift &s    = b.at(label);
          const std::string  name = names.name(label).empty() ?
                                      std::to_string(label) :
                                      names.name(label);
          out << name << ',' << label << ',' << t.volume * ml_per_m3;
          for (const TissueShift *x : {&t, &s})
            {
              for (unsigned int c = 0; c < 3; ++c)
                out << ',' << x->centroid[c] * mm_per_m + 0.;
              out << ',' << x->centroid.norm() * mm_per_m;
            }
          out << ',' << t.max_shift * mm_per_m << ',' << s.max_shift * mm_per_m
              << ',' << ratio(t.centroid.norm(), s.centroid.norm()) << ','
              << ratio(t.max_shift, s.max_shift) << '\n';
        }
    });
    const auto [mean1, max1] =
      nodal_norms(forward.discretization(), prestressed);
    const auto [mean2, max2] =
      nodal_norms(forward.discretization(), stress_free);
    record_scenario_shifts(summary,
                           scenario.output_name(),
                           {mean1, max1},
                           {mean2, max2});
    const auto row = [&](const std::string &what, double x, double y) {
      std::ostringstream line;
      line << "  " << std::left << std::setw(24) << what.substr(0, 24)
           << std::right << std::fixed << std::setprecision(3) << std::setw(13)
           << x * mm_per_m << std::setw(13) << y * mm_per_m << std::setw(8)
           << ratio(x, y) << '\n';
      pcout << line.str();
    };
    pcout << "  shift in mm             pre-stressed  stress-free   ratio\n";
    row("all nodes, mean", mean1, mean2);
    row("all nodes, max", max1, max2);
    for (const auto &[label, t] : a)
      {
        const std::string name = names.name(label).empty() ?
                                   "label " + std::to_string(label) :
                                   names.name(label);
        row(name + ", centroid",
            t.centroid.norm(),
            b.at(label).centroid.norm());
        row(name + ", max", t.max_shift, b.at(label).max_shift);
      }
    pcout << std::flush;

    const double            scale  = output.length_scale();
    const std::string      &unit   = parameters.mesh.length_unit_name;
    std::vector<NodalField> fields = {
      {&prestressed, {"prestressed_shift_" + unit}, scale, ""},
      {&stress_free, {"stress_free_shift_" + unit}, scale, ""}};
    if (contact != nullptr)
      {
        fields.push_back(
          {&contact_fields,
           {"contact_active", "contact_gap_" + unit, "contact_pressure_Pa"},
           1.,
           ""});
      }
    if (parameters.output.write_vtu)
      output.write_fields(forward, 0, 0, fields, {}, scenario.output_name());
  }
} // namespace RestShape
