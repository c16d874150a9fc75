// summary.json: the end of a run and its failure.
#include <restshape/base/version.h>
#include <restshape/postprocess/run_report.h>

namespace RestShape
{
  void
  record_run_failure(Summary &summary, const std::string &failure)
  {
    summary.set("converged", false);
    if (!summary.has("failure"))
      summary.set("failure", failure);
  }

  void
  record_solve_failure(Summary &summary, const SolveStatistics &stats)
  {
    summary.set("converged", false);
    summary.set("failure", stats.failure);
    summary.set("newton_iterations", long(stats.newton_iterations));
  }

  void
  record_run_end(Summary &summary, const double wall_seconds)
  {
    summary.set("wall_seconds", wall_seconds);
    summary.set("restshape_version", std::string(version()));
    summary.set("git_revision", std::string(git_revision()));
  }
} // namespace RestShape
