// Postprocessor: the VTU record of the cycle (Output/Write VTU): contact fields
// and the error indicators; the pre-stressed state of an inverse run.
#ifndef restshape_postprocess_vtu_fields_h
#define restshape_postprocess_vtu_fields_h

#include <restshape/postprocess/postprocessor.h>

namespace RestShape
{
  class VtuFields : public Postprocessor
  {
  public:
    /// @p next_step: the number of the next VTU record (shared with the
    /// inverse iteration's records).
    explicit VtuFields(unsigned int &next_step)
      : next_step(next_step)
    {}

    void
    execute(const PostprocessInput &in) override;

  private:
    unsigned int &next_step;
  };
} // namespace RestShape

#endif
