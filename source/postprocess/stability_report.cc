// summary.json: the stability check.
#include <restshape/postprocess/stability_report.h>

namespace RestShape
{
  void
  record_stability(Summary &summary, const StabilityResult &result)
  {
    summary.set("stability_checked", true);
    summary.set("stable", result.stable());
    summary.set("negative_eigenvalues", long(result.negative_eigenvalues));
    summary.set("smallest_eigenvalue_per_s2", result.smallest_eigenvalue);
  }

  void
  record_stability_not_checked(Summary &summary, const std::string &reason)
  {
    summary.set("stability_checked", false);
    summary.set("stability_not_checked", reason);
  }
} // namespace RestShape
