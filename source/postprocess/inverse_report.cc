// summary.json: the inverse run.
#include <restshape/base/units.h>
#include <restshape/postprocess/inverse_report.h>

namespace RestShape
{
  namespace
  {
    /// With an obstacle: the error to the image, the target's unreachable
    /// part and, where the projection inverted cells, its relaxation.
    void
    record_obstacle_target(Summary &summary, const InverseResult &result)
    {
      summary.set("mean_error_to_image_mm", result.mean_image_error * mm_per_m);
      summary.set("max_error_to_image_mm", result.max_image_error * mm_per_m);
      summary.set("unreachable_target_nodes", long(result.unreachable_nodes));
      summary.set("unreachable_target_max_mm",
                  result.unreachable_max * mm_per_m);
      summary.set("unreachable_target_mean_mm",
                  result.unreachable_mean * mm_per_m);
      // Only where the projection inverted cells (TargetRelaxation).
      const TargetRelaxationResult &relaxed = result.relaxation;
      if (relaxed.inverted_before > 0)
        {
          summary.set("target_cells_inverted_by_projection",
                      long(relaxed.inverted_before));
          summary.set("target_relaxed_nodes", long(relaxed.moved_nodes));
          summary.set("target_relaxation_max_mm",
                      relaxed.largest_change * mm_per_m);
        }
    }
  } // namespace

  void
  record_inverse_result(Summary             &summary,
                        const InverseResult &result,
                        const bool           direct,
                        const bool           with_obstacle)
  {
    summary.set("inverse_iterations", long(result.iterations));
    summary.set("forward_solves", long(result.forward_solves));
    summary.set("rejected_anderson_steps", long(result.rejected_steps));
    if (direct)
      {
        summary.set("direct_inverse_converged", result.direct.converged);
        summary.set("direct_inverse_newton_steps",
                    long(result.direct.newton_steps));
        summary.set("direct_inverse_jacobian_products",
                    long(result.direct.jacobian_products));
      }
    if (const CarriedLoad &carried = result.carried; carried.share > 0)
      {
        summary.set("skull_load_share", carried.share);
        summary.set("reference_skull_force_N", carried.reference_force.norm());
        summary.set("reference_contact_nodes", long(carried.active_nodes));
        summary.set("stated_skull_force_N", carried.stated_force.norm());
      }
    summary.set("mean_error_mm", result.mean_error * mm_per_m);
    summary.set("max_error_mm", result.max_error * mm_per_m);
    if (with_obstacle)
      record_obstacle_target(summary, result);
  }
} // namespace RestShape
