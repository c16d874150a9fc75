// The list of postprocessors and the reductions they share.
#include <deal.II/base/mpi.h>

#include <restshape/base/units.h>
#include <restshape/contact/contact_report.h>
#include <restshape/forward/forward_results.h>
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
    const auto [mean_u, max_u] = nodal_norms(forward.discretization(), u);
    r.mean_displacement_mm     = mean_u * mm_per_m;
    r.max_displacement_mm      = max_u * mm_per_m;
    r.n_nodes =
      Utilities::MPI::sum(double(forward.discretization().owned_nodes().size()),
                          comm);
    r.external = total_external_force(forward, forward.load());
    r.reaction = support_reaction(forward);
    r.contact  = contact ?
                   ContactReport(*contact).total_force(forward.raw_residual()) :
                   Tensor<1, 3>();
    r.support  = elastic_support_force(forward);
    r.surface  = surface_force(forward, forward.load());
    if (contact)
      {
        r.adhesion = ContactReport(*contact).adhesion(forward.raw_residual());
        if (by_label)
          r.contact_by_label =
            ContactReport(*contact).force_by_label(forward.raw_residual());
        r.fixed_planes = ContactReport(*contact).fixed_plane_nodes();
      }
    return r;
  }

  std::vector<std::unique_ptr<Postprocessor>>
  make_postprocessors(const PostprocessParameters &parameters,
                      unsigned int                &next_step)
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
