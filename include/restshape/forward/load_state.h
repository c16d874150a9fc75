// What loads the body at one point of a solve.
#ifndef restshape_forward_load_state_h
#define restshape_forward_load_state_h

#include <deal.II/base/tensor.h>

namespace RestShape
{
  /**
   * The loads of a solve at one load step: a body acceleration (gravity plus
   * any extra field, m/s^2) acting on the mass of the mesh (target)
   * geometry, and the uniform surface pressure (Pa). The hydrostatic
   * pressure of a fluid (Loads/Fluid load) follows the acceleration, so
   * both scale together when the load is stepped.
   */
  struct LoadState
  {
    dealii::Tensor<1, 3> acceleration;
    double               pressure = 0;
  };

  /// The load at fraction @p s of the way from @p start to @p end
  /// (load stepping: s = 0 gives start, s = 1 end).
  inline LoadState
  between(const LoadState &start, const LoadState &end, const double s)
  {
    return LoadState{start.acceleration +
                       s * (end.acceleration - start.acceleration),
                     start.pressure + s * (end.pressure - start.pressure)};
  }
} // namespace RestShape

#endif
