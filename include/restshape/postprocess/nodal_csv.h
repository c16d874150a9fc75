// Postprocessor: nodes.csv (Output/Write nodal CSV): per node its position,
// displacement and rest shift.
#ifndef restshape_postprocess_nodal_csv_h
#define restshape_postprocess_nodal_csv_h

#include <restshape/postprocess/postprocessor.h>

namespace RestShape
{
  class NodalCsv : public Postprocessor
  {
  public:
    void
    execute(const PostprocessInput &in) override;
  };
} // namespace RestShape

#endif
