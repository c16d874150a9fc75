// Postprocessor: the screen lines after a solve: displacement, force balance,
// energy, surface load, elastic support, contact.
#ifndef restshape_postprocess_screen_report_h
#define restshape_postprocess_screen_report_h

#include <restshape/postprocess/postprocessor.h>

namespace RestShape
{
  class ScreenReport : public Postprocessor
  {
  public:
    void
    execute(const PostprocessInput &in) override;
  };
} // namespace RestShape

#endif
