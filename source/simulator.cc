#include <restshape/atomic_file.h>
#include <restshape/input_error.h>
#include <restshape/simulator.h>

#include <iomanip>

namespace RestShape
{
  using namespace dealii;

  Simulator::Simulator(const Parameters &      parameters,
                       const ParameterHandler &prm,
                       const std::string &     prm_file,
                       const MPI_Comm          comm)
    : parameters(parameters)
    , prm(prm)
    , prm_file(prm_file)
    , comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
  {}

  void
  Simulator::run()
  {
    make_mesh();
    check_scene();
    forward = std::make_unique<ForwardProblem>(parameters, *mesh, *materials, timer, pcout);
    if (parameters.contact.enabled())
      {
        contact = std::make_unique<ContactProblem>(parameters.contact, *forward, timer);
        forward->set_contact(contact.get());
      }
    setup_problems();
    check_scene();
    prepare_output();

    SolveStatistics stats;
    for (unsigned int cycle = 0; cycle <= parameters.refinement.cycles; ++cycle)
      {
        if (cycle > 0)
          {
            refine();
            setup_problems();
          }
        pcout << "Cycle " << cycle << ": " << mesh->triangulation().n_global_active_cells()
              << " cells, " << forward->dof_handler().n_dofs() << " DoFs" << std::endl;
        stats = solve_forward();
        postprocess(cycle, stats);
      }
    write_summary(stats);
    timer.print_summary();
  }

  void
  Simulator::setup_problems()
  {
    forward->setup();
    if (contact)
      {
        contact->setup();
        contact->gap_tolerance = parameters.solver.newton_tolerance * mesh->diameter();
        pcout << "Contact: " << parameters.contact.obstacle_file << ", "
              << contact->n_candidates() << " candidate nodes, allowed side: "
              << (parameters.contact.inside ? "inside" : "outside") << std::endl;
      }
  }

  void
  Simulator::make_mesh()
  {
    TimerOutput::Scope scope(timer, "Setup");
    mesh      = std::make_unique<LabelledMesh>(parameters.mesh, comm);
    materials = std::make_unique<MaterialTable>(parameters.materials, mesh->labels());
    if (!parameters.verification.exact_displacement.empty())
      exact = std::make_unique<ExactDisplacement>(parameters.verification.exact_displacement,
                                                  parameters.mesh.length_unit);

    pcout << "Mesh " << parameters.mesh.file << ": "
          << mesh->triangulation().n_global_active_cells()
          << (mesh->is_simplex() ? " tetrahedra" : " hexahedra") << ", labels";
    for (const auto &[label, n] : mesh->label_counts())
      pcout << ' ' << label << " (" << n << " coarse cells)";
    pcout << std::endl;
  }

  void
  Simulator::check_scene() const
  {
    const std::set<Label> labels = mesh->labels();
    const auto            check  = [&](const Label l, const std::string &parameter) {
      if (!labels.count(l))
        throw InputError(prm_file,
                         parameter,
                         "label " + std::to_string(l) +
                           " is not a label of the mesh (labels: " + to_string(labels) + ")");
    };
    for (const auto &f : parameters.boundary.fixed_labels)
      check(f.label, "Boundary conditions/Fixed labels");
    for (const Label l : parameters.loads.pressure_labels)
      check(l, "Loads/Pressure labels");
    if (parameters.refinement.strategy == RefinementParameters::Strategy::adaptive &&
        mesh->is_simplex())
      throw InputError(prm_file,
                       "Adaptive refinement/Strategy",
                       "adaptive refinement needs hexahedra: deal.II 9.4 has no "
                       "hanging-node constraints on tetrahedra; use Mesh/Cell type "
                       "= hexahedra or Strategy = global");
    if (parameters.refinement.strategy == RefinementParameters::Strategy::adaptive)
      throw InputError(prm_file,
                       "Adaptive refinement/Strategy",
                       "adaptive refinement is not available yet; use Strategy = global");

    if (!forward || contact)
      return;
    // Without contact, every displacement component must be fixed
    // somewhere, or rigid-body motion makes the problem singular.
    std::array<double, 3> n_fixed{{0, 0, 0}};
    for (const Node &node : forward->owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        n_fixed[c] += forward->is_fixed(node.dofs[c]);
    for (unsigned int c = 0; c < 3; ++c)
      if (Utilities::MPI::sum(n_fixed[c], comm) == 0)
        throw InputError(prm_file,
                         "Boundary conditions/Fixed labels",
                         std::string("no node is fixed in ") + "xyz"[c] +
                           " and there is no contact: the problem is singular "
                           "(free rigid-body motion); expected fixed labels that "
                           "hold every component");
  }

  void
  Simulator::prepare_output()
  {
    ensure_writable_directory(parameters.output.directory);
    output = std::make_unique<OutputWriter>(parameters.output.directory,
                                            parameters.mesh.length_unit,
                                            comm);
    output->write_text("parameters.prm", [&](std::ostream &out) {
      prm.print_parameters(out, ParameterHandler::PRM);
    });
  }

  SolveStatistics
  Simulator::solve_forward()
  {
    forward->set_state(forward->zero_vector(), forward->zero_vector(), LoadState());
    const SolveStatistics stats = forward->solve(forward->scene_load(), forward->zero_vector());
    pcout << "  Forward solve: " << (stats.converged ? "converged" : "FAILED") << " in "
          << stats.newton_iterations << " Newton iterations, " << stats.load_steps
          << " load step(s)" << std::endl;
    if (!stats.converged)
      {
        write_summary(stats);
        throw SolverFailure("the forward solve did not converge: " + stats.failure);
      }
    return stats;
  }

  void
  Simulator::postprocess(const unsigned int cycle, const SolveStatistics &stats)
  {
    // Nodal displacement from the rest shape, in mm.
    double max_u = 0, sum_u = 0;
    for (const Node &node : forward->owned_nodes())
      {
        Tensor<1, 3> u;
        for (unsigned int c = 0; c < 3; ++c)
          u[c] = forward->displacement()[node.dofs[c]] -
                 forward->rest_displacement()[node.dofs[c]];
        max_u = std::max(max_u, u.norm());
        sum_u += u.norm();
      }
    const double n_nodes = Utilities::MPI::sum(double(forward->owned_nodes().size()), comm);
    max_u                = Utilities::MPI::max(max_u, comm) * 1e3;
    const double mean_u  = Utilities::MPI::sum(sum_u, comm) / n_nodes * 1e3;

    const Tensor<1, 3> external = forward->total_external_force(forward->load());
    const Tensor<1, 3> reaction = forward->support_reaction();
    const Tensor<1, 3> contact_force =
      contact ? contact->total_force(forward->raw_residual()) : Tensor<1, 3>();

    summary.set("converged", true);
    summary.set("cell_type", std::string(mesh->is_simplex() ? "tetrahedra" : "hexahedra"));
    summary.set("polynomial_degree", long(parameters.discretization.degree));
    summary.set("tangent",
                std::string(parameters.discretization.tangent == TangentType::consistent ?
                              "consistent" :
                              "warped"));
    summary.set("n_cells", long(mesh->triangulation().n_global_active_cells()));
    summary.set("n_nodes", long(n_nodes));
    summary.set("n_dofs", long(forward->dof_handler().n_dofs()));
    summary.set("newton_iterations", long(stats.newton_iterations));
    summary.set("load_steps", long(stats.load_steps));
    summary.set("relative_residual", stats.residual / stats.reference);
    summary.set("max_displacement_mm", max_u);
    summary.set("mean_displacement_mm", mean_u);
    summary.set("external_force_N", external);
    summary.set("support_reaction_N", reaction);
    summary.set("force_balance_relative",
                (external + reaction + contact_force).norm() / std::max(external.norm(), 1e-300));
    if (contact)
      {
        summary.set("active_contact_nodes", long(contact->n_active()));
        summary.set("contact_force_N", contact_force);
        summary.set("active_set_iterations", long(stats.active_set_changes + 1));
        summary.set("max_penetration_mm", contact->max_penetration(true) * 1e3 + 0.);
        summary.set("nodes_outside", long(contact->n_outside()));
        const auto [p_min, p_max] = contact->pressure_range(forward->raw_residual());
        summary.set("contact_pressure_min_Pa", p_min);
        summary.set("contact_pressure_max_Pa", p_max);
      }

    convergence_table.add_value("cycle", cycle);
    convergence_table.add_value("cells", mesh->triangulation().n_global_active_cells());
    convergence_table.add_value("dofs", forward->dof_handler().n_dofs());
    std::vector<double> row = {double(cycle),
                               double(mesh->triangulation().n_global_active_cells()),
                               double(forward->dof_handler().n_dofs()),
                               double(stats.newton_iterations),
                               max_u};
    if (exact)
      {
        const DisplacementErrors e = exact->errors(*forward);
        convergence_table.add_value("L2_rel", e.l2_relative);
        convergence_table.add_value("H1_rel", e.h1_relative);
        convergence_table.add_value("max_nodal_mm", e.max_nodal_error * 1e3);
        for (const char *key : {"L2_rel", "H1_rel", "max_nodal_mm"})
          {
            convergence_table.set_scientific(key, true);
            convergence_table.set_precision(key, 3);
          }
        row.insert(row.end(), {e.l2_relative, e.h1_relative, e.max_nodal_error * 1e3});
        summary.set("l2_error_relative", e.l2_relative);
        summary.set("h1_error_relative", e.h1_relative);
        summary.set("max_nodal_error_mm", e.max_nodal_error * 1e3);
        pcout << "  Error against the exact displacement: L2 " << e.l2_relative << ", H1 "
              << e.h1_relative << " (relative), max nodal " << e.max_nodal_error * 1e3 << " mm"
              << std::endl;
      }
    row.push_back(wall_timer.wall_time());
    convergence_rows.push_back(row);

    std::vector<std::string> header = {"cycle", "n_cells", "n_dofs", "newton_iterations",
                                       "max_displacement_mm"};
    if (exact)
      header.insert(header.end(), {"l2_error_relative", "h1_error_relative", "max_nodal_error_mm"});
    header.push_back("wall_seconds");
    output->write_csv("convergence.csv", header, convergence_rows);
    if (exact && cycle > 0)
      {
        ConvergenceTable table = convergence_table;
        table.evaluate_convergence_rates("L2_rel", ConvergenceTable::reduction_rate_log2);
        table.evaluate_convergence_rates("H1_rel", ConvergenceTable::reduction_rate_log2);
        output->write_text("convergence.txt", [&](std::ostream &out) { table.write_text(out); });
        if (cycle == parameters.refinement.cycles)
          table.write_text(pcout.get_stream());
      }

    pcout << "  Displacement: max " << max_u << " mm, mean " << mean_u << " mm; force balance "
          << (external + reaction + contact_force).norm() << " N of " << external.norm() << " N"
          << std::endl;
    if (contact)
      pcout << "  Contact: " << contact->n_active() << " active nodes, force " << contact_force
            << " N, largest penetration " << contact->max_penetration(true) * 1e3 << " mm"
            << std::endl;
    if (parameters.output.write_vtu)
      {
        TimerOutput::Scope scope(timer, "Output");
        std::vector<NodalField> fields;
        VectorType              contact_fields;
        if (contact)
          {
            contact_fields.reinit(forward->locally_owned_dofs(),
                                  forward->locally_relevant_dofs(),
                                  comm);
            contact_fields = contact->nodal_fields(forward->raw_residual(),
                                                   1. / parameters.mesh.length_unit);
            fields.push_back({&contact_fields,
                              {"contact_active",
                               "contact_gap_" + parameters.mesh.length_unit_name,
                               "contact_pressure_Pa"},
                              1.});
          }
        output->write_fields(*forward, cycle, cycle, fields);
      }
  }

  void
  Simulator::refine()
  {
    TimerOutput::Scope scope(timer, "Refinement");
    mesh->refine_global();
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
    output->write_text("summary.json", [&](std::ostream &out) { summary.write(out); });
  }
} // namespace RestShape
