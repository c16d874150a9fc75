// The list of postprocessors and the reductions they share.
#include <deal.II/base/mpi.h>

#include <restshape/base/units.h>
#include <restshape/postprocess/convergence_postprocessor.h>
#include <restshape/postprocess/nodal_csv.h>
#include <restshape/postprocess/postprocessor.h>
#include <restshape/postprocess/screen_report.h>
#include <restshape/postprocess/summary_postprocessor.h>
#include <restshape/postprocess/vtu_fields.h>

namespace RestShape
{
  using namespace dealii;

  SolveReductions
  compute_reductions(const ForwardProblem &forward,
                     const ContactProblem *contact,
                     const VectorType     &u,
                     const bool            by_label,
                     const MPI_Comm        comm)
  {
    SolveReductions r;
    const auto [mean_u, max_u] = forward.nodal_norms(u);
    r.mean_displacement_mm     = mean_u * mm_per_m;
    r.max_displacement_mm      = max_u * mm_per_m;
    r.n_nodes = Utilities::MPI::sum(double(forward.owned_nodes().size()), comm);
    r.external = forward.total_external_force(forward.load());
    r.reaction = forward.support_reaction();
    r.contact =
      contact ? contact->total_force(forward.raw_residual()) : Tensor<1, 3>();
    r.support = forward.elastic_support_force();
    r.surface = forward.surface_force(forward.load());
    if (contact)
      {
        r.adhesion = contact->adhesion(forward.raw_residual());
        if (by_label)
          r.contact_by_label = contact->force_by_label(forward.raw_residual());
        r.fixed_planes = contact->fixed_plane_nodes();
      }
    return r;
  }

  std::vector<std::unique_ptr<Postprocessor>>
  make_postprocessors(const Parameters &parameters, unsigned int &next_step)
  {
    std::vector<std::unique_ptr<Postprocessor>> list;
    list.push_back(std::make_unique<SummaryPostprocessor>());
    list.push_back(std::make_unique<ConvergencePostprocessor>());
    list.push_back(std::make_unique<ScreenReport>());
    if (parameters.output.write_nodal_csv)
      list.push_back(std::make_unique<NodalCsv>());
    if (parameters.output.write_vtu)
      list.push_back(std::make_unique<VtuFields>(next_step));
    return list;
  }
} // namespace RestShape
