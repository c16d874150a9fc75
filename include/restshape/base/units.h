// Unit conversions: everything inside is SI; reports are in mm.
#ifndef restshape_base_units_h
#define restshape_base_units_h

namespace RestShape
{
  /// Millimetres per metre: lengths (m) are multiplied by it for reports
  /// (screen, summary.json, CSV), which are in mm.
  constexpr double mm_per_m = 1e3;
} // namespace RestShape

#endif
