// Postprocessor: summary.json: the solve, displacement, distance to a carried
// target, forces and contact conditions; prints the distance to the target and
// the error estimate.
#ifndef restshape_postprocess_summary_postprocessor_h
#define restshape_postprocess_summary_postprocessor_h

#include <restshape/postprocess/postprocessor.h>

namespace RestShape
{
  class SummaryPostprocessor : public Postprocessor
  {
  public:
    void
    execute(const PostprocessInput &in) override;
  };
} // namespace RestShape

#endif
