// summary.json after a solve.
#include <restshape/base/units.h>
#include <restshape/contact/contact_report.h>
#include <restshape/forward/forward_results.h>
#include <restshape/postprocess/summary_postprocessor.h>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// A tissue's name as a JSON key: its label name, else "label_N".
    std::string
    tissue_key(const LabelledMesh &mesh, const Label label)
    {
      const std::string name = mesh.label_names().name(label);
      return name.empty() ? "label_" + std::to_string(label) : name;
    }

    /// Contact figures: active set, force, the strict conditions, fixed
    /// planes, adhesion, pressures and the patch.
    void
    set_contact(const PostprocessInput &in)
    {
      const ContactProblem &contact = *in.contact;
      Summary              &summary = in.summary;
      summary.set("active_contact_nodes",
                  long(ContactReport(contact).n_active()));
      summary.set("contact_force_N", in.reductions.contact);
      // What the obstacle carries at the target, tissue by tissue: it
      // tells which rest shape the inverse problem chose (doc/inverse.md).
      if (in.parameters.inverse.enabled)
        for (const auto &[label, f] : in.reductions.contact_by_label)
          summary.set("contact_force_" + tissue_key(in.mesh, label) + "_N", f);
      summary.set("active_set_iterations",
                  long(in.stats.active_set_changes + 1));
      const ContactConditions &conditions = in.forward.contact_conditions();
      summary.set("contact_conditions_hold", conditions.satisfied());
      summary.set("max_penetration_mm", conditions.max_penetration * mm_per_m);
      summary.set("max_pull_Pa", conditions.pulling.worst);
      summary.set("nodes_off_obstacle", long(conditions.off.nodes));
      summary.set("nodes_outside", long(conditions.outside));
      const auto [n_fixed, fixed_distance] = in.reductions.fixed_planes;
      summary.set("fixed_plane_nodes", long(n_fixed));
      summary.set("fixed_plane_distance_mm", fixed_distance * mm_per_m + 0.);
      const ContactReport::Adhesion &adhesion = in.reductions.adhesion;
      summary.set("adhesive_contact_nodes", long(adhesion.nodes));
      summary.set("adhesive_force_N", adhesion.force);
      summary.set("adhesive_force_fraction", adhesion.fraction);
      const auto [p_min, p_max] =
        ContactReport(contact).pressure_range(in.forward.raw_residual());
      summary.set("contact_pressure_min_Pa", p_min);
      summary.set("contact_pressure_max_Pa", p_max);
      summary.set("contact_patch_radius_mm",
                  ContactReport(contact).patch_radius(in.reductions.contact) *
                    mm_per_m);
    }

    /// A forward run from a rest_shape.msh that carries the equilibrium
    /// of the inverse run that wrote it: how far this run's equilibrium
    /// is from it (the round trip; where the target crosses the obstacle
    /// the error against the target includes what no equilibrium reaches).
    void
    set_equilibrium_distance(const PostprocessInput &in)
    {
      const RestShapeNodes &nodes = in.mesh.rest_shape_nodes();
      if (nodes.equilibria.empty())
        return;
      const RestShapeNodeLookup    lookup(nodes);
      const std::vector<Point<3>> &vertices =
        in.mesh.triangulation().get_vertices();
      std::vector<Point<3>> equilibria(vertices.size());
      for (unsigned int v = 0; v < vertices.size(); ++v)
        equilibria[v] = lookup.equilibrium(vertices[v]).value_or(vertices[v]);
      const auto [mean_e, max_e] = distance_to(in.forward, equilibria);
      in.summary.set("equilibrium_distance_mean_mm", mean_e * mm_per_m);
      in.summary.set("equilibrium_distance_max_mm", max_e * mm_per_m);
      in.pcout << "  Equilibrium vs the equilibrium carried by "
               << in.parameters.mesh.file << ": mean " << mean_e * mm_per_m
               << " mm, max " << max_e * mm_per_m << " mm" << std::endl;
    }

    /// A forward run from a rest shape: how far the equilibrium is from
    /// the mesh geometry, or from the target a rest_shape.msh carries.
    void
    set_target_error(const PostprocessInput &in)
    {
      const PostprocessParameters &p = in.parameters;
      if (p.inverse.enabled ||
          (p.mesh.rest_shape_file.empty() && in.mesh.targets().empty()))
        return;
      const bool from_rest_file = !p.mesh.rest_shape_file.empty();
      const auto [mean_e, max_e] =
        from_rest_file ?
          nodal_norms(in.forward.discretization(), in.forward.displacement()) :
          distance_to(in.forward, in.mesh.targets());
      in.summary.set("mean_error_mm", mean_e * mm_per_m);
      in.summary.set("max_error_mm", max_e * mm_per_m);
      in.pcout << (from_rest_file ?
                     "  Equilibrium vs mesh geometry" :
                     "  Equilibrium vs the target carried by " + p.mesh.file)
               << ": mean " << mean_e * mm_per_m << " mm, max "
               << max_e * mm_per_m << " mm" << std::endl;
      set_equilibrium_distance(in);
    }
  } // namespace

  void
  SummaryPostprocessor::execute(const PostprocessInput &in)
  {
    const PostprocessParameters &p       = in.parameters;
    const SolveStatistics       &stats   = in.stats;
    const SolveReductions       &r       = in.reductions;
    Summary                     &summary = in.summary;
    summary.set("converged", true);
    summary.set("cell_type",
                std::string(in.mesh.is_simplex() ? "tetrahedra" : "hexahedra"));
    summary.set("polynomial_degree", long(p.forward.discretization.degree));
    summary.set("tangent", p.forward.discretization.tangent_name);
    summary.set("formulation",
                p.forward.discretization.mixed ? "mixed" : "displacement");
    if (p.forward.discretization.mixed &&
        !p.forward.discretization.nodal_pressure)
      summary.set("cell_pressure",
                  std::string(p.forward.discretization.linear_cell_pressure ?
                                "linear" :
                                "constant"));
    if (p.forward.discretization.nodal_pressure)
      summary.set("nodal_pressure_boundary",
                  std::string(
                    p.forward.discretization.boundary_shares_to_interior ?
                      "interior" :
                      "own"));
    if (!p.forward.discretization.formulation_note.empty())
      summary.set("formulation_note",
                  p.forward.discretization.formulation_note);
    // The displacement formulation forced where a Poisson's ratio is 0.49
    // or above: it locks (the run's warning, for scripts and studies).
    if (!p.forward.discretization.formulation_warning.empty())
      summary.set("formulation_warning",
                  p.forward.discretization.formulation_warning);
    summary.set("n_cells",
                long(in.mesh.triangulation().n_global_active_cells()));
    summary.set("n_nodes", long(r.n_nodes));
    summary.set("n_dofs",
                long(in.forward.discretization().dof_handler().n_dofs()));
    summary.set("newton_iterations", long(stats.newton_iterations));
    summary.set("load_steps", long(stats.load_steps));
    if (in.forward.linear_solver_kind() == LinearSolverType::cg_amg)
      summary.set("linear_iterations_per_newton_step",
                  double(stats.linear_iterations) /
                    std::max(1u, stats.newton_iterations));
    if (!p.inverse.enabled)
      {
        // The residual reached, and whether it met the tolerance or Newton
        // stopped at the measured round-off level of the state above it.
        summary.set("relative_residual", stats.residual / stats.reference);
        summary.set("newton_tolerance_met", !stats.at_round_off);
        if (stats.at_round_off)
          summary.set("round_off_level_relative", stats.round_off);
      }
    summary.set("max_displacement_mm", r.max_displacement_mm);
    summary.set("mean_displacement_mm", r.mean_displacement_mm);
    summary.set("potential_energy_J", in.forward.potential_energy());
    set_target_error(in);
    summary.set("external_force_N", r.external);
    summary.set("surface_force_N", r.surface);
    summary.set("support_reaction_N", r.reaction);
    summary.set("force_balance_relative",
                r.imbalance() / std::max(r.external.norm(), 1e-300));
    if (in.forward.loads().has_support())
      summary.set("elastic_support_force_N", r.support);
    if (in.contact)
      set_contact(in);

    summary.set("estimated_error_relative", in.estimate.relative);
    in.pcout << "  Estimated error ("
             << (p.refinement.estimator ==
                     RefinementParameters::Estimator::kelly ?
                   "Kelly" :
                   "traction jump")
             << ", relative H1): " << in.estimate.relative << std::endl;
  }
} // namespace RestShape
