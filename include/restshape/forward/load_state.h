// What loads the body at one point of a solve.
#ifndef restshape_forward_load_state_h
#define restshape_forward_load_state_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace RestShape
{
  /**
   * The loads of a solve at one load step, all acting on the mass of the
   * mesh (target) geometry:
   *
   * - acceleration (m/s^2): gravity and any field that acts like it, on the
   *   tissue's density less the fluid's with Loads/Fluid load = buoyancy (on
   *   the full density with hydrostatic pressure, whose surface pressure
   *   follows this acceleration);
   * - pressure: the uniform surface pressure (Pa);
   * - tissue_acceleration (m/s^2): a body force per unit mass on the tissue
   *   alone, never buoyed (a force field as in Table 1 of Morin et al.);
   * - drained_acceleration (m/s^2) with fluid_level (m): the buoyancy lost
   *   where the fluid is drained, rho_fluid drained_acceleration on the
   *   tissue above the free surface through fluid_level (above: against
   *   drained_acceleration, in the mesh geometry). Drained to a level under
   *   gravity g: drained_acceleration = g.
   *
   * - opening_pressure (Pa): the uniform pressure taken off the pressure
   *   faces of an opening of the skull (ForwardProblem::open_surface()):
   *   they carry p(x) - opening_pressure.
   *
   * Every term is linear in its vector, so the difference of two load
   * states (what a scenario changes) is a load state too.
   */
  struct LoadState
  {
    dealii::Tensor<1, 3> acceleration;
    double               pressure = 0;
    dealii::Tensor<1, 3> tissue_acceleration;
    dealii::Tensor<1, 3> drained_acceleration;
    dealii::Point<3>     fluid_level;
    double               opening_pressure = 0;
  };

  /// The load at fraction @p s of the way from @p start to @p end
  /// (load stepping: s = 0 gives start, s = 1 end). The fluid level is the
  /// end's where it drains, else the start's.
  inline LoadState
  between(const LoadState &start, const LoadState &end, const double s)
  {
    LoadState load;
    load.acceleration =
      start.acceleration + s * (end.acceleration - start.acceleration);
    load.pressure = start.pressure + s * (end.pressure - start.pressure);
    load.tissue_acceleration =
      start.tissue_acceleration +
      s * (end.tissue_acceleration - start.tissue_acceleration);
    load.drained_acceleration =
      start.drained_acceleration +
      s * (end.drained_acceleration - start.drained_acceleration);
    load.opening_pressure = start.opening_pressure +
                            s * (end.opening_pressure - start.opening_pressure);
    load.fluid_level = end.drained_acceleration.norm_square() > 0 ?
                         end.fluid_level :
                         start.fluid_level;
    return load;
  }

  /// @p a - @p b: what changes from @p b to @p a (the fluid level is
  /// @p a's where it drains, else @p b's).
  inline LoadState
  difference(const LoadState &a, const LoadState &b)
  {
    LoadState d;
    d.acceleration         = a.acceleration - b.acceleration;
    d.pressure             = a.pressure - b.pressure;
    d.tissue_acceleration  = a.tissue_acceleration - b.tissue_acceleration;
    d.drained_acceleration = a.drained_acceleration - b.drained_acceleration;
    d.opening_pressure     = a.opening_pressure - b.opening_pressure;
    d.fluid_level =
      a.drained_acceleration.norm_square() > 0 ? a.fluid_level : b.fluid_level;
    return d;
  }
} // namespace RestShape

#endif
