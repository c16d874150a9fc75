// What summary.json says of a run as a whole: its end (the version and the
// wall time) and why it failed.
#ifndef restshape_postprocess_run_report_h
#define restshape_postprocess_run_report_h

#include <restshape/io/output.h>

#include <string>

namespace RestShape
{
  /// converged = false, and @p failure unless a failure is already
  /// recorded (the first cause is the one that counts).
  void
  record_run_failure(Summary &summary, const std::string &failure);

  /// An unconverged solve: converged = false, its failure (replacing an
  /// earlier one) and its Newton iterations.
  void
  record_solve_failure(Summary &summary, const SolveStatistics &stats);

  /// The last entries of every summary.json: the wall time of the run
  /// (s), the program's version and its git revision.
  void
  record_run_end(Summary &summary, const double wall_seconds);
} // namespace RestShape

#endif
