// Simulator: what a run reports after each solve (screen, summary.json,
// VTU, convergence table).
#include <deal.II/distributed/tria.h>

#include <restshape/app/simulator.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/forward/load_scales.h>
#include <restshape/forward/stability.h>
#include <restshape/forward/state_transfer.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/mesh_pieces.h>

#include <iomanip>

namespace RestShape
{
  using namespace dealii;

  void
  Simulator::postprocess(const unsigned int cycle, const SolveStatistics &stats)
  {
    // Nodal displacement from the rest shape, in mm.
    VectorType u = forward->owned_copy(forward->displacement());
    u -= forward->owned_copy(forward->rest_displacement());
    const auto [mean_u_m, max_u_m] = forward->nodal_norms(u);
    const double mean_u = mean_u_m * 1e3, max_u = max_u_m * 1e3;
    const double n_nodes =
      Utilities::MPI::sum(double(forward->owned_nodes().size()), comm);

    const Tensor<1, 3> external =
      forward->total_external_force(forward->load());
    const Tensor<1, 3> reaction = forward->support_reaction();
    const Tensor<1, 3> contact_force =
      contact ? contact->total_force(forward->raw_residual()) : Tensor<1, 3>();
    const Tensor<1, 3> support_force = forward->elastic_support_force();

    summary.set("converged", true);
    summary.set("cell_type",
                std::string(mesh->is_simplex() ? "tetrahedra" : "hexahedra"));
    summary.set("polynomial_degree", long(parameters.discretization.degree));
    summary.set("tangent", parameters.discretization.tangent_name);
    summary.set("n_cells", long(mesh->triangulation().n_global_active_cells()));
    summary.set("n_nodes", long(n_nodes));
    summary.set("n_dofs", long(forward->dof_handler().n_dofs()));
    summary.set("newton_iterations", long(stats.newton_iterations));
    summary.set("load_steps", long(stats.load_steps));
    if (forward->linear_solver_kind() == LinearSolverType::cg_amg)
      summary.set("linear_iterations_per_newton_step",
                  double(stats.linear_iterations) /
                    std::max(1u, stats.newton_iterations));
    if (!parameters.inverse.enabled)
      summary.set("relative_residual", stats.residual / stats.reference);
    summary.set("max_displacement_mm", max_u);
    summary.set("mean_displacement_mm", mean_u);
    summary.set("potential_energy_J", forward->potential_energy());
    if (!parameters.inverse.enabled && !parameters.mesh.rest_shape_file.empty())
      {
        // Started from a rest shape: how far the equilibrium is from the
        // mesh (target) geometry.
        const auto [mean_e, max_e] =
          forward->nodal_norms(forward->displacement());
        summary.set("mean_error_mm", mean_e * 1e3);
        summary.set("max_error_mm", max_e * 1e3);
        pcout << "  Equilibrium vs mesh geometry: mean " << mean_e * 1e3
              << " mm, max " << max_e * 1e3 << " mm" << std::endl;
      }
    else if (!parameters.inverse.enabled && !mesh->targets().empty())
      {
        // A rest shape that carries its target (rest_shape.msh).
        const auto [mean_e, max_e] = forward->distance_to(mesh->targets());
        summary.set("mean_error_mm", mean_e * 1e3);
        summary.set("max_error_mm", max_e * 1e3);
        pcout << "  Equilibrium vs the target carried by "
              << parameters.mesh.file << ": mean " << mean_e * 1e3
              << " mm, max " << max_e * 1e3 << " mm" << std::endl;
      }
    summary.set("external_force_N", external);
    const Tensor<1, 3> surface = forward->surface_force(forward->load());
    summary.set("surface_force_N", surface);
    summary.set("support_reaction_N", reaction);
    summary.set("force_balance_relative",
                (external + reaction + contact_force + support_force).norm() /
                  std::max(external.norm(), 1e-300));
    if (parameters.boundary.support_stiffness > 0)
      summary.set("elastic_support_force_N", support_force);
    if (contact)
      {
        summary.set("active_contact_nodes", long(contact->n_active()));
        summary.set("contact_force_N", contact_force);
        summary.set("active_set_iterations",
                    long(stats.active_set_changes + 1));
        const ContactConditions &conditions = forward->contact_conditions();
        summary.set("contact_conditions_hold", conditions.satisfied());
        summary.set("max_penetration_mm", conditions.max_penetration * 1e3);
        summary.set("max_pull_Pa", conditions.pulling.worst);
        summary.set("nodes_off_obstacle", long(conditions.off.nodes));
        summary.set("nodes_outside", long(conditions.outside));
        const auto [n_fixed, fixed_distance] = contact->fixed_plane_nodes();
        summary.set("fixed_plane_nodes", long(n_fixed));
        summary.set("fixed_plane_distance_mm", fixed_distance * 1e3 + 0.);
        const ContactProblem::Adhesion adhesion =
          contact->adhesion(forward->raw_residual());
        summary.set("adhesive_contact_nodes", long(adhesion.nodes));
        summary.set("adhesive_force_N", adhesion.force);
        summary.set("adhesive_force_fraction", adhesion.fraction);
        const auto [p_min, p_max] =
          contact->pressure_range(forward->raw_residual());
        summary.set("contact_pressure_min_Pa", p_min);
        summary.set("contact_pressure_max_Pa", p_max);
        summary.set("contact_patch_radius_mm",
                    contact->patch_radius(contact_force) * 1e3);
      }

    {
      TimerOutput::Scope scope(timer, "Error estimate");
      estimate = estimate_error(*forward, u, parameters.refinement.estimator);
    }
    summary.set("estimated_error_relative", estimate.relative);
    pcout << "  Estimated error ("
          << (parameters.refinement.estimator ==
                  RefinementParameters::Estimator::kelly ?
                "Kelly" :
                "traction jump")
          << ", relative H1): " << estimate.relative << std::endl;

    convergence_table.add_value("cycle", cycle);
    convergence_table.add_value("cells",
                                mesh->triangulation().n_global_active_cells());
    convergence_table.add_value("dofs", forward->dof_handler().n_dofs());
    std::vector<double>      row    = {double(cycle),
                                       double(
                                 mesh->triangulation().n_global_active_cells()),
                                       double(forward->dof_handler().n_dofs()),
                                       estimate.relative,
                                       double(stats.newton_iterations),
                                       max_u,
                                       forward->potential_energy()};
    std::vector<std::string> header = {"cycle",
                                       "n_cells",
                                       "n_dofs",
                                       "estimated_error",
                                       "newton_iterations",
                                       "max_displacement_mm",
                                       "potential_energy_J"};
    std::vector<std::string> rated;
    const auto               add_errors = [&](const ExactDisplacement &e,
                                const VectorType        &field,
                                const std::string       &prefix,
                                const std::string       &key) {
      const DisplacementErrors errors = e.errors(*forward, field);
      convergence_table.add_value(prefix + "L2_rel", errors.l2_relative);
      convergence_table.add_value(prefix + "H1_rel", errors.h1_relative);
      convergence_table.add_value(prefix + "max_nodal_mm",
                                  errors.max_nodal_error * 1e3);
      for (const std::string k : {"L2_rel", "H1_rel", "max_nodal_mm"})
        {
          convergence_table.set_scientific(prefix + k, true);
          convergence_table.set_precision(prefix + k, 3);
        }
      rated.insert(rated.end(), {prefix + "L2_rel", prefix + "H1_rel"});
      row.insert(row.end(),
                 {errors.l2_relative,
                  errors.h1_relative,
                  errors.max_nodal_error * 1e3});
      header.insert(header.end(),
                    {key + "l2_error_relative",
                     key + "h1_error_relative",
                     key + "max_nodal_error_mm"});
      summary.set(key + "l2_error_relative", errors.l2_relative);
      summary.set(key + "h1_error_relative", errors.h1_relative);
      summary.set(key + "max_nodal_error_mm", errors.max_nodal_error * 1e3);
      pcout << "  Error of the "
            << (key.empty() ? "displacement" : "rest shape")
            << " against the exact one: L2 " << errors.l2_relative << ", H1 "
            << errors.h1_relative << " (relative), max nodal "
            << errors.max_nodal_error * 1e3 << " mm" << std::endl;
    };
    if (exact)
      add_errors(*exact, u, "", "");
    if (exact_rest)
      add_errors(*exact_rest, forward->rest_displacement(), "rest_", "rest_");
    if (parameters.inverse.enabled)
      {
        row.push_back(inverse_result.mean_error * 1e3);
        header.push_back("mean_error_mm");
      }
    row.push_back(wall_timer.wall_time());
    header.push_back("wall_seconds");
    convergence_rows.push_back(row);
    output->write_csv("convergence.csv", header, convergence_rows);
    if (!rated.empty() && cycle > 0)
      {
        ConvergenceTable table = convergence_table;
        for (const std::string &key : rated)
          table.evaluate_convergence_rates(
            key, ConvergenceTable::reduction_rate_log2);
        output->write_text("convergence.txt",
                           [&](std::ostream &out) { table.write_text(out); });
        if (cycle == parameters.refinement.cycles)
          table.write_text(pcout.get_stream());
      }

    pcout << "  Displacement: max " << max_u << " mm, mean " << mean_u
          << " mm; force balance "
          << (external + reaction + contact_force + support_force).norm()
          << " N of " << external.norm() << " N; potential energy "
          << forward->potential_energy() << " J" << std::endl;
    if (forward->surface_load().acts(forward->load()))
      pcout << "  Surface pressure: resultant " << surface << " N ("
            << (forward->surface_load().follower() ? "follower" : "dead")
            << " load)" << std::endl;
    if (parameters.boundary.support_stiffness > 0)
      pcout << "  Elastic support: force " << support_force << " N"
            << std::endl;
    if (contact)
      {
        const ContactConditions &conditions = forward->contact_conditions();
        pcout << "  Contact: " << contact->n_active() << " active nodes, force "
              << contact_force << " N, largest penetration "
              << conditions.max_penetration * 1e3 << " mm; "
              << conditions.text() << std::endl;
        if (conditions.outside > 0)
          pcout << "  Contact: " << conditions.outside
                << " candidate nodes lie beyond the obstacle (they started "
                   "there and are free until they come back in)"
                << std::endl;
        const auto [n_fixed, fixed_distance] = contact->fixed_plane_nodes();
        if (n_fixed > 0)
          pcout << "  Contact: " << n_fixed
                << " nodes on fixed planes (their planes kept changing), up "
                   "to "
                << fixed_distance * 1e3 << " mm off the obstacle surface"
                << std::endl;
        const ContactProblem::Adhesion adhesion =
          contact->adhesion(forward->raw_residual());
        if (adhesion.nodes > 0)
          pcout << "  Contact: " << adhesion.nodes
                << " active nodes pull on the obstacle (accepted), with "
                << adhesion.force << " N, " << 100 * adhesion.fraction
                << " % of the contact force" << std::endl;
      }
    if (parameters.output.write_nodal_csv)
      {
        TimerOutput::Scope scope(timer, "Output");
        const VectorType w = forward->owned_copy(forward->rest_displacement());
        std::vector<std::vector<double>> rows;
        for (const Node &node : forward->owned_nodes())
          {
            std::vector<double> row;
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(node.position[c] * output->length_scale());
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(u[node.dofs[c]] * 1e3);
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(w[node.dofs[c]] * 1e3);
            rows.push_back(row);
          }
        std::vector<std::vector<double>> all_rows;
        for (const auto &part : Utilities::MPI::gather(comm, rows))
          all_rows.insert(all_rows.end(), part.begin(), part.end());
        const std::string unit = parameters.mesh.length_unit_name;
        output->write_csv("nodes.csv",
                          {"x_" + unit,
                           "y_" + unit,
                           "z_" + unit,
                           "u_x_mm",
                           "u_y_mm",
                           "u_z_mm",
                           "rest_shift_x_mm",
                           "rest_shift_y_mm",
                           "rest_shift_z_mm"},
                          all_rows);
      }
    if (parameters.output.write_vtu)
      {
        TimerOutput::Scope      scope(timer, "Output");
        std::vector<NodalField> fields;
        VectorType              contact_fields;
        if (contact)
          {
            contact_fields = contact->nodal_fields(forward->raw_residual(),
                                                   output->length_scale());
            fields.push_back(
              {&contact_fields,
               {"contact_active",
                "contact_gap_" + parameters.mesh.length_unit_name,
                "contact_pressure_Pa"},
               1.,
               ""});
          }
        // The inverse iteration wrote its series; its final state is also
        // the pre-stressed state a later simulation can start from.
        const std::vector<CellField> cells = {
          {"estimated_error", estimate.indicators}};
        if (parameters.inverse.enabled)
          output->write_fields(
            *forward, 0, 0, fields, cells, "prestressed_state");
        else
          output->write_fields(*forward, next_step++, cycle, fields, cells);
      }
  }

  void
  Simulator::write_summary(const SolveStatistics &stats)
  {
    if (!stats.converged)
      {
        summary.set("converged", false);
        summary.set("failure", stats.failure);
        summary.set("newton_iterations", long(stats.newton_iterations));
      }
    summary.set("wall_seconds", wall_timer.wall_time());
    output->write_text("summary.json",
                       [&](std::ostream &out) { summary.write(out); });
  }
} // namespace RestShape
