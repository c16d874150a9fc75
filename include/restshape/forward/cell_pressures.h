// The cells' pressures of the mixed formulation with a pressure per cell,
// as the three-field Newton step of a caller other than the forward
// Newton solve keeps them (the direct inverse, whose unknown is the rest
// shape). Each assembly records every cell's mean dilatation J_mean and
// the derivatives U'(J_mean) and U''(J_mean) of its volumetric energy;
// a caller may shift the pressure the assembly uses on each cell, in the
// residual and in the tangent, from the condensed U'(J_mean) to
// U'(J_mean) + offset: the derivative of that residual at the state the
// offsets were taken at is the three-field tangent with the pressure p =
// U'(J_mean) + offset, whatever second-order change of volume the last
// step left in U'(J_mean) (K times it: 5,000 times mu at nu = 0.4999).
#ifndef restshape_forward_cell_pressures_h
#define restshape_forward_cell_pressures_h

#include <utility>
#include <vector>

namespace RestShape
{
  /// The volumetric state of a point that carries a pressure of the
  /// mixed formulation (a cell with a pressure of its own; a vertex of
  /// the averaged nodal pressure) at an assembly.
  struct PressurePoint
  {
    double J   = 1; // volume ratio: current over rest volume
    double dU  = 0; // U'(J) (Pa): the condensed pressure, -p in compression
    double d2U = 0; // its derivative in J (Pa)
  };

  class CellPressures
  {
  public:
    /// @p n_cells active cells; no offsets.
    void
    reset(const unsigned int n_cells)
    {
      records.assign(n_cells, PressurePoint());
      offsets.clear();
    }
    /// Record the state of the cell of active index @p cell.
    void
    record(const unsigned int cell, const PressurePoint &c)
    {
      if (cell < records.size())
        records[cell] = c;
    }
    /// The pressure the assembly uses on @p cell, given its condensed
    /// pressure U'(J_mean) (Pa).
    double
    pressure(const unsigned int cell, const double condensed) const
    {
      return cell < offsets.size() ? condensed + offsets[cell] : condensed;
    }
    /// Whether offsets are set.
    bool
    shifted() const
    {
      return !offsets.empty();
    }
    /// The records of the last assembly (by active cell index; only the
    /// locally owned cells' are meaningful).
    const std::vector<PressurePoint> &
    last() const
    {
      return records;
    }
    /// Offsets (Pa) by active cell index; empty: none.
    void
    set_offsets(std::vector<double> o)
    {
      offsets = std::move(o);
    }

  private:
    std::vector<PressurePoint> records;
    std::vector<double>        offsets;
  };
} // namespace RestShape

#endif
