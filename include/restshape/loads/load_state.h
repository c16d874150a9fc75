// What loads the body at one point of a solve.
#ifndef restshape_loads_load_state_h
#define restshape_loads_load_state_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace RestShape
{
  /**
   * A fluid's hydrostatic pressure field, weight rho_f max(0, a . (x -
   * level)) in Pa at x: a (m/s^2) the acceleration it is under, level (m)
   * a point of its free surface, rho_f the fluid's density.
   */
  struct FluidColumn
  {
    dealii::Tensor<1, 3> acceleration;
    dealii::Point<3>     level;
    double               weight = 1;
  };

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
   * - fluid (Loads/Fluid load = hydrostatic pressure): the fluid's
   *   pressure on the pressure faces, a sum of FluidColumn fields;
   * - opening_pressure (Pa) and opening_fluid: the uniform and the fluid
   *   pressure taken off the pressure faces of an opening of the skull
   *   (ForwardProblem::open_surface()).
   * - terms: the weight of the loads of the registry's load terms
   *   (load_terms.h, e.g. Surface traction): 1 in the scene's load, 0
   *   unloaded.
   *
   * Every term is linear in its vector or weight, so the difference of two
   * load states (what a scenario changes) is a load state too.
   */
  struct LoadState
  {
    dealii::Tensor<1, 3>     acceleration;
    double                   pressure = 0;
    dealii::Tensor<1, 3>     tissue_acceleration;
    dealii::Tensor<1, 3>     drained_acceleration;
    dealii::Point<3>         fluid_level;
    std::vector<FluidColumn> fluid;
    double                   opening_pressure = 0;
    std::vector<FluidColumn> opening_fluid;
    double                   terms = 0;
  };

  /// @p a weighted by @p wa plus @p b weighted by @p wb, columns of the
  /// same acceleration and level merged, those of weight 0 dropped.
  inline std::vector<FluidColumn>
  combine(const std::vector<FluidColumn> &a,
          const double                    wa,
          const std::vector<FluidColumn> &b,
          const double                    wb)
  {
    std::vector<FluidColumn> sum;
    const auto               add = [&sum](const FluidColumn &c, double w) {
      for (FluidColumn &s : sum)
        if (s.acceleration == c.acceleration && s.level == c.level)
          {
            s.weight += w * c.weight;
            return;
          }
      sum.push_back({c.acceleration, c.level, w * c.weight});
    };
    for (const FluidColumn &c : a)
      add(c, wa);
    for (const FluidColumn &c : b)
      add(c, wb);
    std::vector<FluidColumn> kept;
    for (const FluidColumn &c : sum)
      if (c.weight != 0)
        kept.push_back(c);
    return kept;
  }

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
    load.fluid = combine(start.fluid, 1 - s, end.fluid, s);
    load.opening_fluid =
      combine(start.opening_fluid, 1 - s, end.opening_fluid, s);
    load.terms       = start.terms + s * (end.terms - start.terms);
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
    d.fluid                = combine(a.fluid, 1, b.fluid, -1);
    d.opening_fluid        = combine(a.opening_fluid, 1, b.opening_fluid, -1);
    d.terms                = a.terms - b.terms;
    d.fluid_level =
      a.drained_acceleration.norm_square() > 0 ? a.fluid_level : b.fluid_level;
    return d;
  }
} // namespace RestShape

#endif
