// What summary.json says of a brain-shift scenario: its keys are prefixed
// by the scenario's output name @p name ("scenario" or "scenario_NAME"),
// as in "scenario_NAME_contact_force_N".
#ifndef restshape_postprocess_scenario_report_h
#define restshape_postprocess_scenario_report_h

#include <restshape/io/output.h>
#include <restshape/postprocess/postprocessor.h>

#include <string>
#include <utility>

namespace RestShape
{
  /// A craniotomy: the contact nodes it freed and the pressure faces in it.
  void
  record_scenario_opening(Summary           &summary,
                          const std::string &name,
                          const unsigned int freed_contact_nodes,
                          const unsigned int pressure_faces);

  /// What carries the changed load at the pre-stressed model's end state
  /// (N).
  void
  record_scenario_forces(Summary               &summary,
                         const std::string     &name,
                         const SolveReductions &reductions);

  /// The Newton iterations of the two models.
  /// NAME_converged = true.
  void
  record_scenario_success(Summary &summary, const std::string &name);

  /// NAME_converged = false and NAME_failure = @p reason.
  void
  record_scenario_failure(Summary           &summary,
                          const std::string &name,
                          const std::string &reason);

  void
  record_scenario_newton(Summary               &summary,
                         const std::string     &name,
                         const SolveStatistics &prestressed,
                         const SolveStatistics &stress_free);

  /// The mean and largest nodal shift (m) of the two models.
  void
  record_scenario_shifts(Summary                         &summary,
                         const std::string               &name,
                         const std::pair<double, double> &prestressed,
                         const std::pair<double, double> &stress_free);
} // namespace RestShape

#endif
