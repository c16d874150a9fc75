// The parameters of subsection Loads.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/loads/load_parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  LoadParameters::declare_parameters(ParameterHandler &prm)
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
    prm.declare_entry("Surface pressure",
                      "0",
                      Patterns::Double(),
                      "Uniform pressure in Pa on the outer surface (e.g. "
                      "CSF), along the inward normal of the faces; see "
                      "Pressure load.");
    prm.declare_entry(
      "Pressure load",
      "follower",
      Patterns::Selection("follower|dead"),
      "follower: the pressure acts on the current (deformed) surface along "
      "its current normal, in every solve (a fluid's pressure; Newton uses "
      "its exact tangent). dead: the same tractions fixed on the faces of "
      "Mesh/File, whatever the body does (right only where the equilibrium "
      "is the mesh geometry itself).");
    prm.declare_entry("Pressure labels",
                      "",
                      Patterns::Anything(),
                      "The pressure acts on the outer faces of cells with "
                      "these labels; empty: all labels that are not fully "
                      "fixed.");
    prm.leave_subsection();
  }

  void
  LoadParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    gravity       = parse_vector(prm.get("Gravity"), "Loads/Gravity");
    pressure      = prm.get_double("Surface pressure");
    follower      = prm.get("Pressure load") == "follower";
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
        fluid_level = dealii::Point<3>(
          parse_vector(prm.get("Fluid level"), "Loads/Fluid level"));
      }
    pressure_labels =
      parse_label_set(prm.get("Pressure labels"), "Loads/Pressure labels");
    prm.leave_subsection();
  }
} // namespace RestShape
