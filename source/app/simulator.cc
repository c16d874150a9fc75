#include <deal.II/distributed/tria.h>

#include <restshape/app/rest_shape_file.h>
#include <restshape/app/run_size.h>
#include <restshape/app/scenario.h>
#include <restshape/app/simulator.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/base/interruption.h>
#include <restshape/base/units.h>
#include <restshape/base/version.h>
#include <restshape/contact/admissible_target.h>
#include <restshape/contact/contact_report.h>
#include <restshape/forward/forward_results.h>
#include <restshape/forward/load_scales.h>
#include <restshape/forward/stability.h>
#include <restshape/forward/state_transfer.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/mesh_pieces.h>
#include <restshape/postprocess/inverse_report.h>
#include <restshape/postprocess/run_report.h>
#include <restshape/postprocess/stability_report.h>

#include <cmath>
#include <iomanip>

namespace RestShape
{
  using namespace dealii;

  Simulator::Simulator(const Parameters       &parameters,
                       const ParameterHandler &prm,
                       const std::string      &prm_file,
                       const MPI_Comm          comm)
    : parameters(parameters)
    , postprocess_parameters(parameters.postprocess_parameters())
    , prm(prm)
    , prm_file(prm_file)
    , comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
  {}

  void
  Simulator::run()
  {
    try
      {
        run_phases();
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const ScenarioFailure &)
      {
        // Its summary is written: the rest shape converged.
        throw;
      }
    catch (const OutputFailure &e)
      {
        // Partial results are no results: removed, and the summary says
        // why where the disk still takes it.
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          remove_previous_results(parameters.output.directory);
        record_failure(e.what());
        throw;
      }
    catch (const SolverFailure &e)
      {
        // A piece that only a hinge holds is the likely cause: say so.
        const std::string pieces = unheld_pieces_text();
        if (pieces.empty())
          {
            record_failure(e.what());
            throw;
          }
        summary.set("unheld_pieces", pieces);
        record_failure(e.what());
        throw SolverFailure(std::string(e.what()) + "; " + pieces);
      }
    catch (const std::exception &e)
      {
        // Every run that stops after it began to write its results leaves
        // a summary.json that says why, never the previous run's.
        record_failure(e.what());
        throw;
      }
  }

  void
  Simulator::record_failure(const std::string &what)
  {
    if (!output)
      return;
    record_run_failure(summary, what);
    record_run_end(summary, wall_timer.wall_time());
    // Not collective: the failure may be this rank's alone.
    output->try_write_text("summary.json",
                           [&](std::ostream &out) { summary.write(out); });
  }

  void
  Simulator::run_phases()
  {
    make_mesh();
    check_scene_on_mesh();
    forward = std::make_unique<ForwardProblem>(
      parameters.forward, *mesh, *materials, timer, pcout);
    if (parameters.contact.enabled())
      {
        contact = std::make_unique<ContactProblem>(
          parameters.contact,
          forward->discretization(),
          *forward,
          parameters.forward.solver.newton_tolerance,
          materials->max_youngs_modulus(),
          timer);
        forward->set_contact(contact.get());
      }
    setup_problems();
    check_scene_on_problem();
    report_load_scales();
    VectorType rest = initial_rest_shape();
    prepare_output();

    SolveStatistics           stats;
    std::optional<VectorType> guess = target_guess();
    for (unsigned int cycle = 0; cycle <= parameters.refinement.cycles; ++cycle)
      {
        if (cycle > 0)
          refine(rest, guess);
        pcout << "Cycle " << cycle << ": "
              << mesh->triangulation().n_global_active_cells() << " cells, "
              << forward->discretization().dof_handler().n_dofs() << " DoFs"
              << (!guess     ? "" :
                  cycle == 0 ? ", starting from the equilibrium (else the "
                               "target) the rest mesh carries" :
                               ", starting from the previous cycle's solution")
              << std::endl;
        const VectorType *start = guess ? &*guess : nullptr;
        stats = parameters.inverse.enabled ? solve_inverse(cycle, rest, start) :
                                             solve_forward(rest, start);
        // The final equilibrium is the result; earlier cycles only lead
        // to it (the check would cost each of them as much again).
        if (cycle == parameters.refinement.cycles)
          check_stability_of_equilibrium(stats);
        // The next solve is on a refined mesh or a prestress comparison:
        // the error estimator gets the AMG's or factorisation's memory.
        forward->release_linear_solver();
        postprocess(cycle, stats);
      }
    const std::vector<std::string> failed = run_scenarios();
    if (!std::cout.good())
      summary.set("screen_output",
                  std::string("lost: stdout was closed (broken pipe)"));
    write_summary(stats);
    timer.print_summary();
    if (!failed.empty())
      throw ScenarioFailure(scenario_failure_text(failed));
  }

  std::vector<std::string>
  Simulator::run_scenarios()
  {
    std::vector<std::string> failed;
    for (const ScenarioParameters &scenario : parameters.scenarios)
      if (!run_scenario(scenario))
        failed.push_back(scenario.section());
    if (!parameters.scenarios.empty())
      summary.set("scenarios_converged", failed.empty());
    return failed;
  }

  std::string
  Simulator::scenario_failure_text(const std::vector<std::string> &failed) const
  {
    std::string names;
    for (const std::string &name : failed)
      names += (names.empty() ? "" : ", ") + name;
    return std::to_string(failed.size()) + " of " +
           std::to_string(parameters.scenarios.size()) +
           " scenarios did not converge (" + names +
           "; summary.json gives each one's failure); the " +
           (parameters.inverse.enabled ? "rest shape" : "equilibrium") +
           " converged and its results are written";
  }

  void
  Simulator::make_mesh()
  {
    TimerOutput::Scope scope(timer, "Setup");
    const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
    mesh                    = std::make_unique<LabelledMesh>(
      parameters.mesh, comm, [&](const std::size_t cells) {
        check_run_size(cells, parameters, prm_file, root);
      });
    materials = std::make_unique<MaterialTable>(parameters.forward.materials,
                                                mesh->labels());
    if (!parameters.verification.exact_displacement.empty())
      exact = std::make_unique<ExactDisplacement>(
        parameters.verification.exact_displacement,
        parameters.mesh.length_unit);
    if (!parameters.verification.exact_rest_displacement.empty())
      exact_rest = std::make_unique<ExactDisplacement>(
        parameters.verification.exact_rest_displacement,
        parameters.mesh.length_unit,
        "Verification/Exact rest displacement");
    for (const auto *solution : {exact.get(), exact_rest.get()})
      if (solution)
        solution->check_finite_on(mesh->triangulation());

    pcout << "Mesh " << parameters.mesh.file << ": "
          << mesh->triangulation().n_global_active_cells()
          << (mesh->is_simplex() ? " tetrahedra" : " hexahedra") << ", labels";
    // An atlas has hundreds of labels: then only their list.
    constexpr std::size_t max_listed = 12;
    if (mesh->label_counts().size() > max_listed)
      pcout << ' ' << to_string(mesh->labels()) << " ("
            << mesh->label_counts().size() << " labels)";
    else
      for (const auto &[label, n] : mesh->label_counts())
        {
          const std::string name = mesh->label_names().name(label);
          pcout << ' ' << label << " (" << (name.empty() ? "" : name + ", ")
                << n << " coarse cells)";
        }
    pcout << std::endl;
    const auto [gap, where] = mesh->narrowest_gap();
    if (std::isfinite(gap))
      pcout << "  " << describe_surface_gap(gap * mm_per_m, where * mm_per_m)
            << " (thin flaps border narrow gaps; doc/brain.md)" << std::endl;
  }

  void
  Simulator::setup_problems()
  {
    forward->setup();
    if (contact)
      {
        contact->setup();
        check_obstacle_placement();
        const ContactReport report(*contact);
        const unsigned int  walls = report.n_cavity_wall_faces();
        pcout << "Contact: " << parameters.contact.obstacle_file << ", "
              << report.n_candidates() << " candidate nodes, allowed side: "
              << (parameters.contact.inside ? "inside" : "outside")
              << (walls > 0 ? ", " + std::to_string(walls) +
                                " faces of cavity walls left out" :
                              "")
              << std::endl;
      }
  }

  std::optional<VectorType>
  Simulator::target_guess() const
  {
    // A forward run from a rest_shape.msh: Newton starts at the full load
    // from the equilibrium the inverse run found (the file carries it;
    // an older file: its target). A rest shape may lie beyond the
    // obstacle (the one-sided rule of the inverse), and a solve ramped
    // from it would first push those nodes onto the obstacle: on the
    // cutting skull at P2 that inverted cells. If Newton fails from
    // there, the solve starts again from the rest shape.
    if (parameters.inverse.enabled || mesh->targets().empty())
      return std::nullopt;
    if (std::optional<VectorType> d =
          equilibrium_of_rest_shape_file(*forward, *mesh))
      return d;
    const std::vector<Point<3>> &targets = mesh->targets();
    const auto               &vertices   = mesh->triangulation().get_vertices();
    std::vector<Tensor<1, 3>> shift(vertices.size());
    for (unsigned int v = 0; v < targets.size() && v < vertices.size(); ++v)
      shift[v] = targets[v] - vertices[v];
    return forward->discretization().interpolate_vertex_field(shift);
  }

  void
  Simulator::refine(VectorType &rest, std::optional<VectorType> &guess)
  {
    TimerOutput::Scope             scope(timer, "Refinement");
    std::unique_ptr<StateTransfer> transfer;
    const auto                     prepare = [&]() {
      if (parameters.refinement.transfer_solution)
        transfer = std::make_unique<StateTransfer>(
          *forward,
          std::vector<const VectorType *>{&forward->displacement(),
                                          &forward->rest_displacement()});
    };
    if (parameters.refinement.strategy ==
        RefinementParameters::Strategy::adaptive)
      mesh->refine_adaptive(estimate.indicators,
                            parameters.refinement.refine_fraction,
                            parameters.refinement.coarsen_fraction,
                            prepare);
    else
      mesh->refine_global(prepare);
    setup_problems();
    guess.reset();
    rest = forward->discretization().zero_vector();
    if (!transfer)
      return;
    std::vector<VectorType> fields = transfer->interpolate(*forward);
    unsigned int            n_bad  = 0;
    if (!rest_shape_is_valid(forward->discretization(), fields[1], n_bad))
      {
        // The rest shape was checked at the coarse mesh's quadrature
        // points only.
        pcout << "  The previous rest shape inverts " << n_bad
              << " cells of the refined mesh: starting from the unloaded "
                 "mesh and the target shape"
              << std::endl;
        return;
      }
    guess = std::move(fields[0]);
    rest  = std::move(fields[1]);
  }

  VectorType
  Simulator::initial_rest_shape() const
  {
    if (parameters.mesh.rest_shape_file.empty())
      {
        // A quadratic rest shape's curved edges (a rest_shape.msh of P2).
        if (std::optional<VectorType> w =
              rest_shape_of_edge_nodes(*forward, *mesh))
          {
            pcout << "Rest shape: the edge nodes of the quadratic cells "
                     "where the mesh file puts them"
                  << std::endl;
            return *w;
          }
        return forward->discretization().zero_vector();
      }
    const std::vector<Point<3>> rest =
      mesh->read_rest_shape(parameters.mesh.rest_shape_file);
    const auto               &vertices = mesh->triangulation().get_vertices();
    std::vector<Tensor<1, 3>> w(rest.size());
    for (unsigned int v = 0; v < rest.size(); ++v)
      w[v] = rest[v] - vertices[v];
    const VectorType result =
      forward->discretization().interpolate_vertex_field(w);
    unsigned int n_bad = 0;
    if (!rest_shape_is_valid(forward->discretization(), result, n_bad))
      throw InputError(parameters.mesh.rest_shape_file,
                       "Mesh/Rest shape file",
                       std::to_string(n_bad) +
                         " cells are inverted relative to the mesh");
    pcout << "Rest shape: " << parameters.mesh.rest_shape_file << std::endl;
    return result;
  }

  void
  Simulator::prepare_output()
  {
    ensure_writable_directory(parameters.output.directory);
    // One run per directory: rank 0 owns it, and a refusal ends every
    // rank alike.
    std::string owned;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          claim_directory(parameters.output.directory);
        }
      catch (const InputError &e)
        {
          owned = e.message;
        }
    owned = Utilities::MPI::broadcast(comm, owned, 0);
    if (!owned.empty())
      throw InputError(parameters.output.directory, "Output/Directory", owned);
    output = std::make_unique<OutputWriter>(parameters.output.directory,
                                            parameters.mesh.length_unit,
                                            comm);
    // From here on the directory holds this run's results only: the
    // previous run's are removed, and summary.json says that this run has
    // not finished until it has (and what stopped it, if it is
    // interrupted). An interruption waits until both hold.
    const std::string unfinished =
      "{\n  \"converged\": false,\n  \"restshape_version\": \"" +
      std::string(version()) + "\",\n  \"git_revision\": \"" + git_revision() +
      "\",";
    {
      const InterruptionsDeferred previous_or_new;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        remove_previous_results(parameters.output.directory);
      output->write_text("summary.json", [&](std::ostream &out) {
        out << unfinished
            << "\n  \"failure\": \"the run has not finished (it is running, "
               "or it was killed)\"\n}\n";
      });
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        set_interrupted_summary(output->path("summary.json"), unfinished);
    }
    output->write_text("parameters.prm", [&](std::ostream &out) {
      out << "# The effective parameters of a run of "
          << version_text("restshape") << "\n";
      prm.print_parameters(out, ParameterHandler::PRM);
    });
    // The name of each value of the VTU's label field.
    if (!mesh->label_names().empty())
      output->write_text("label_names.txt", [&](std::ostream &out) {
        write_label_names(mesh->label_names(), out);
      });
  }

  SolveStatistics
  Simulator::solve_forward(const VectorType &rest, const VectorType *guess)
  {
    // A forward simulation brings nodes that start beyond the obstacle
    // onto it (the one-sided rule is the inverse iteration's): say so.
    std::string beyond;
    if (contact && guess == nullptr)
      {
        const auto n = nodal_norms_above(forward->discretization(),
                                         AdmissibleTarget(*contact).shift(),
                                         0.);
        if (n.n > 0)
          {
            beyond = std::to_string(n.n) +
                     " contact nodes of the mesh start beyond the obstacle "
                     "(by up to " +
                     number_text(n.max * mm_per_m) + " mm)";
            pcout << "Contact: " << beyond
                  << ": the forward solve brings them onto it" << std::endl;
          }
      }
    SolveStatistics stats =
      forward->solve_from(guess, forward->loads().scene_load(), rest);
    pcout << "  Forward solve: " << (stats.converged ? "converged" : "FAILED")
          << " in " << stats.newton_iterations << " Newton iterations, "
          << stats.load_steps << " load step(s)" << std::endl;
    if (!stats.converged)
      {
        if (!beyond.empty())
          stats.failure += "; " + beyond +
                           ", which the solve had to push onto it (a "
                           "forward simulation starts inside the obstacle)";
        write_summary(stats);
        throw SolverFailure("the forward solve did not converge: " +
                            stats.failure);
      }
    return stats;
  }

  SolveStatistics
  Simulator::solve_inverse(const unsigned int cycle,
                           const VectorType  &initial_rest,
                           const VectorType  *guess)
  {
    inverse        = std::make_unique<InverseProblem>(parameters.inverse,
                                               *forward,
                                               contact.get(),
                                               parameters.output.write_vtu ?
                                                        output.get() :
                                                        nullptr,
                                               timer,
                                               pcout,
                                               wall_timer);
    inverse_result = inverse->run(initial_rest, next_step, guess);
    next_step += inverse->records().size();

    for (const InverseIterationRecord &r : inverse->records())
      iteration_rows.push_back({double(r.iteration),
                                r.mean_error * mm_per_m,
                                r.max_error * mm_per_m,
                                r.mean_image_error * mm_per_m,
                                r.max_image_error * mm_per_m,
                                double(r.newton_iterations),
                                double(r.active_contact_nodes),
                                r.wall_seconds,
                                double(r.anderson),
                                double(cycle)});
    output->write_csv("iterations.csv",
                      {"iteration",
                       "mean_error_mm",
                       "max_error_mm",
                       "mean_error_to_image_mm",
                       "max_error_to_image_mm",
                       "newton_iterations",
                       "active_contact_nodes",
                       "wall_seconds",
                       "anderson_step",
                       "cycle"},
                      iteration_rows);

    record_inverse_result(summary,
                          inverse_result,
                          parameters.inverse.method ==
                            InverseParameters::Method::direct,
                          contact != nullptr);

    SolveStatistics stats;
    stats.converged         = inverse_result.converged;
    stats.newton_iterations = inverse_result.newton_iterations;
    stats.load_steps        = 1;
    stats.reference         = 1;
    if (!inverse_result.converged)
      {
        stats.failure = inverse_result.reason;
        // Whether the iteration had a stable target to converge to (if it
        // reached an equilibrium at all).
        if (inverse_result.forward_solves > 0 &&
            stability_not_checked_because().empty())
          {
            const std::string unstable = stability_text();
            stats.failure += unstable.empty() ?
                               "; the last equilibrium is stable" :
                               "; the last equilibrium is " + unstable;
          }
        write_summary(stats);
        throw SolverFailure("the inverse iteration did not converge: " +
                            stats.failure);
      }
    pcout << "  Rest shape found in " << inverse_result.iterations
          << " iterations (" << inverse_result.forward_solves
          << " forward solves, " << inverse_result.newton_iterations
          << " Newton iterations): mean error "
          << inverse_result.mean_error * mm_per_m << " mm, max "
          << inverse_result.max_error * mm_per_m << " mm" << std::endl;

    write_rest_shape();
    return stats;
  }

  void
  Simulator::write_rest_shape() const
  {
    // The p4est triangulation of a rank holds only its part of a refined
    // mesh: the whole rest shape is not known on any one rank.
    if (dynamic_cast<const parallel::distributed::Triangulation<3> *>(
          &mesh->triangulation()) != nullptr &&
        Utilities::MPI::n_mpi_processes(comm) > 1)
      {
        pcout << "  rest_shape.msh is not written: hexahedra on several "
                 "ranks (p4est) hold no rank with the whole mesh; run on one "
                 "rank or with tetrahedra"
              << std::endl;
        return;
      }
    const VectorType     &w        = forward->rest_displacement();
    const auto           &vertices = mesh->triangulation().get_vertices();
    std::vector<Point<3>> rest_positions(vertices);
    for (const auto &cell :
         forward->discretization().dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          for (unsigned int c = 0; c < 3; ++c)
            rest_positions[cell->vertex_index(v)][c] =
              vertices[cell->vertex_index(v)][c] +
              w[cell->vertex_dof_index(v, c)];
    // It remembers its target (the mesh) and the image's masses, so that a
    // forward run from it alone reaches the target with the same mass.
    // Rank 0 writes it; a failure ends every rank.
    const std::string file = output->path("rest_shape.msh");
    write_on_every_rank(
      comm,
      file,
      [&]() {
        // On one rank: each node's equilibrium and a quadratic rest
        // shape's edge nodes, for the round trip.
        mesh->write_gmsh(rest_positions,
                         file,
                         image_mass_ratios(*forward),
                         Utilities::MPI::n_mpi_processes(comm) == 1 ?
                           rest_nodes_of(*forward) :
                           LabelledMesh::RestNodes());
      },
      true);
  }

  std::string
  Simulator::stability_not_checked_because() const
  {
    if (parameters.forward.solver.check_stability == StabilityCheck::off)
      return "Solver/Check stability = false";
    if (!forward->loads().symmetric())
      return "the follower pressure acts on a surface with free edges: its "
             "tangent is not symmetric, and stability is then not a question "
             "of the energy";
    return free_dofs_missing(*forward);
  }

  std::string
  Simulator::stability_text()
  {
    TimerOutput::Scope scope(timer, "Stability");
    StabilityResult    s;
    try
      {
        s = check_stability(*forward);
      }
    catch (const SolverFailure &e)
      {
        // Inner solves of an indefinite tangent may fail with CG + AMG.
        const std::string reason =
          std::string("its linear solves failed: ") + e.what();
        record_stability_not_checked(summary, reason);
        pcout << "  Stability: not determined (" << reason << ")" << std::endl;
        return "";
      }
    record_stability(summary, s);
    std::string how = s.variant_text();
    if (!s.mass_text().empty())
      how += (how.empty() ? "" : "; ") + s.mass_text();
    pcout << "  Stability: " << s.text()
          << (how.empty() ? "" : " (" + how + ")") << std::endl;
    return s.stable() ? std::string() : s.text();
  }

  void
  Simulator::check_stability_of_equilibrium(const SolveStatistics &stats)
  {
    const std::string skip = stability_not_checked_because();
    if (!skip.empty())
      {
        record_stability_not_checked(summary, skip);
        pcout << "  Stability: not checked (" << skip << ")" << std::endl;
        return;
      }
    const std::string unstable = stability_text();
    if (unstable.empty())
      return;
    SolveStatistics failed = stats;
    failed.converged       = false;
    failed.failure =
      (parameters.inverse.enabled ?
         "no stable rest shape reaches the target: its equilibrium is " :
         "the equilibrium is ") +
      unstable;
    write_summary(failed);
    throw SolverFailure(failed.failure);
  }

  bool
  Simulator::run_scenario(const ScenarioParameters &parameters_of_scenario)
  {
    Scenario scenario(parameters,
                      parameters_of_scenario,
                      *forward,
                      contact.get(),
                      *output,
                      summary,
                      pcout);
    return scenario.run();
  }

} // namespace RestShape
