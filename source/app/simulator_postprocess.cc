// Simulator: the postprocessors after each solve (postprocess/), and
// summary.json at the end.
#include <deal.II/distributed/tria.h>

#include <restshape/app/simulator.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/forward/load_scales.h>
#include <restshape/forward/stability.h>
#include <restshape/forward/state_transfer.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/mesh_pieces.h>
#include <restshape/postprocess/run_report.h>

#include <iomanip>

namespace RestShape
{
  using namespace dealii;

  void
  Simulator::postprocess(const unsigned int cycle, const SolveStatistics &stats)
  {
    // Nodal displacement from the rest shape.
    VectorType u =
      forward->discretization().owned_copy(forward->displacement());
    u -= forward->discretization().owned_copy(forward->rest_displacement());
    const SolveReductions reductions = compute_reductions(
      *forward, contact.get(), u, parameters.inverse.enabled, comm);
    {
      TimerOutput::Scope scope(timer, "Error estimate");
      estimate = estimate_error(*forward, u, parameters.refinement.estimator);
    }
    if (inverse)
      {
        TimerOutput::Scope scope(timer, "Output");
        inverse->rewrite_final_output(
          {{"estimated_error", estimate.indicators}});
      }
    if (postprocessors.empty())
      postprocessors = make_postprocessors(postprocess_parameters, next_step);
    const PostprocessInput in{postprocess_parameters,
                              *mesh,
                              *forward,
                              contact.get(),
                              stats,
                              cycle,
                              u,
                              reductions,
                              estimate,
                              exact.get(),
                              exact_rest.get(),
                              inverse_result.mean_error,
                              wall_timer.wall_time(),
                              summary,
                              *output,
                              pcout,
                              timer};
    for (const auto &p : postprocessors)
      p->execute(in);
  }

  void
  Simulator::write_summary(const SolveStatistics &stats)
  {
    if (!stats.converged)
      record_solve_failure(summary, stats);
    record_run_end(summary, wall_timer.wall_time());
    output->write_text("summary.json",
                       [&](std::ostream &out) { summary.write(out); });
  }
} // namespace RestShape
