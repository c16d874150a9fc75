// What summary.json says of the stability check of an equilibrium.
#ifndef restshape_postprocess_stability_report_h
#define restshape_postprocess_stability_report_h

#include <restshape/forward/stability.h>
#include <restshape/io/output.h>

#include <string>

namespace RestShape
{
  /// Checked: whether stable, the negative eigenvalues found and the
  /// smallest eigenvalue (1/s^2).
  void
  record_stability(Summary &summary, const StabilityResult &result);

  /// Not checked (or not determined), and why.
  void
  record_stability_not_checked(Summary &summary, const std::string &reason);
} // namespace RestShape

#endif
