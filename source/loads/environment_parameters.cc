// The parameters of subsection Loads that describe the body's environment:
// gravity and the immersing fluid.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/loads/environment_parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  EnvironmentParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    prm.declare_entry("Gravity",
                      "0, 0, -9.81",
                      Patterns::Anything(),
                      "Gravitational acceleration in m/s^2, 'x, y, z' in the "
                      "mesh's coordinate frame.");
    prm.declare_entry("Fluid density",
                      "0",
                      Patterns::Double(),
                      "Density in kg/m^3 of a fluid the body is immersed in "
                      "(CSF: about 1007); how it acts is set by Fluid load. "
                      "0: no fluid.");
    prm.declare_entry(
      "Fluid load",
      "buoyancy",
      Patterns::Selection("buoyancy|hydrostatic pressure"),
      "How the fluid of Fluid density acts. buoyancy: every body force acts "
      "on the density minus the fluid's (Archimedes' resultant, as if the "
      "whole body were immersed; a brain of 1040 kg/m^3 in CSF weighs 3.2 % "
      "of its weight). hydrostatic pressure: the full density, and on the "
      "pressure faces below the Fluid level the pressure "
      "rho_fluid a . (x - x_level) in Pa (a: the body acceleration, x the "
      "current position), added to Surface pressure; what CSF does on a "
      "surface whose other parts are held (a closed immersed surface "
      "receives exactly its buoyancy).");
    prm.declare_entry("Fluid level",
                      "",
                      Patterns::Anything(),
                      "A point 'x, y, z' (mesh length unit) on the fluid's "
                      "free surface, which is normal to the body "
                      "acceleration; faces above it are drained. Empty: the "
                      "highest point of the pressure faces (the whole "
                      "surface is wetted). Only with Fluid load = "
                      "hydrostatic pressure.");
    prm.leave_subsection();
  }

  void
  EnvironmentParameters::parse_parameters(ParameterHandler &prm,
                                          const double      length_unit)
  {
    prm.enter_subsection("Loads");
    gravity       = parse_vector(prm.get("Gravity"), "Loads/Gravity");
    fluid_density = prm.get_double("Fluid density");
    if (!(fluid_density >= 0))
      throw InputError("",
                       "Loads/Fluid density",
                       "'" + prm.get("Fluid density") +
                         "': expected a density >= 0 in kg/m^3");
    hydrostatic = prm.get("Fluid load") == "hydrostatic pressure";
    if (hydrostatic && fluid_density == 0)
      throw InputError("",
                       "Loads/Fluid load",
                       "hydrostatic pressure needs the fluid's density: "
                       "expected Loads/Fluid density > 0 in kg/m^3");
    has_fluid_level = !dealii::Utilities::trim(prm.get("Fluid level")).empty();
    if (has_fluid_level)
      {
        if (!hydrostatic)
          throw InputError("",
                           "Loads/Fluid level",
                           "a fluid level needs Fluid load = hydrostatic "
                           "pressure");
        fluid_level =
          dealii::Point<3>(length_unit * parse_vector(prm.get("Fluid level"),
                                                      "Loads/Fluid level"));
      }
    prm.leave_subsection();
  }
} // namespace RestShape
