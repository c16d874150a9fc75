// What summary.json says of an inverse run: its iterations, the direct
// inverse, the load the skull carries, the error to the target and, with an
// obstacle, to the image and the part of the target no equilibrium reaches.
#ifndef restshape_postprocess_inverse_report_h
#define restshape_postprocess_inverse_report_h

#include <restshape/inverse/inverse_problem.h>
#include <restshape/io/output.h>

namespace RestShape
{
  /// @p direct: Inverse/Method = direct; @p with_obstacle: a skull or
  /// cavity acts (the admissible target may differ from the image).
  void
  record_inverse_result(Summary             &summary,
                        const InverseResult &result,
                        const bool           direct,
                        const bool           with_obstacle);
} // namespace RestShape

#endif
