// What surrounds the body, shared by the load terms that act through it:
// gravity and the immersing fluid (CSF), subsection Loads.
#ifndef restshape_loads_environment_parameters_h
#define restshape_loads_environment_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace RestShape
{
  /**
   * Loads/Gravity, Fluid density, Fluid load and Fluid level: the body
   * acceleration and the fluid the body is immersed in. The body force
   * (body_force.h) buoys the tissue by the fluid (Fluid load = buoyancy);
   * the surface pressure (surface_pressure.h) carries the fluid's
   * hydrostatic pressure (Fluid load = hydrostatic pressure).
   */
  struct EnvironmentParameters
  {
    dealii::Tensor<1, 3> gravity;           // m/s^2
    double               fluid_density = 0; // kg/m^3 of an immersing fluid
    /// The fluid acts as hydrostatic pressure on the pressure faces (else:
    /// as buoyancy, a reduced density).
    bool             hydrostatic     = false;
    bool             has_fluid_level = false;
    dealii::Point<3> fluid_level; // m, on the free surface

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// @p length_unit: metres per unit of the mesh, in which Fluid level
    /// is given. Throws InputError naming the parameter.
    void
    parse_parameters(dealii::ParameterHandler &prm, const double length_unit);
  };
} // namespace RestShape

#endif
