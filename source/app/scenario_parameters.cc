// The parameters of subsection Scenario.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameters.h>
#include <restshape/contact/obstacle.h>

#include <cmath>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Largest rotation angle accepted, in degrees.
    constexpr double max_angle_degrees = 360;
  } // namespace

  void
  ScenarioParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scenario");
    prm.declare_entry(
      "Enabled",
      "false",
      Patterns::Bool(),
      "After the inverse problem, change the loads as given below and "
      "solve (1) the pre-stressed model, from its equilibrium under the "
      "scene's loads to the changed loads, and (2) the model stress-free in "
      "the same geometry and contact state (the pre-stressed model's "
      "equilibrium), under the change alone. Writes scenario.csv (shift of "
      "every tissue's centroid and its largest nodal shift, both models, "
      "and their ratio) and scenario.vtu (both shift fields).");
    prm.declare_entry("Gravity rotation",
                      "0, 0, 0",
                      Patterns::Anything(),
                      "The head turned: Loads/Gravity rotated by these "
                      "angles in degrees about the mesh's x, then y, then z "
                      "axis ('180, 0, 0': supine to prone about x). "
                      "Buoyancy turns with it.");
    prm.declare_entry("Fluid level",
                      "",
                      Patterns::Anything(),
                      "CSF drained to a level: a point 'x, y, z' (mesh length "
                      "unit) of the new free surface, normal to gravity (the "
                      "rotated one). Tissue above it (in the mesh geometry) "
                      "loses its buoyancy. Empty: no drainage. Needs "
                      "Loads/Fluid load = buoyancy.");
    prm.declare_entry(
      "Surface pressure",
      "",
      Patterns::Anything(),
      "The uniform surface pressure in Pa on the Loads/Pressure "
      "labels after the change (0: atmospheric, as in an "
      "opened skull). Empty: unchanged.");
    prm.declare_entry("Tissue body force",
                      "0, 0, 0",
                      Patterns::Anything(),
                      "A body force per unit mass in m/s^2 ('x, y, z') on "
                      "the tissue alone, not buoyed: a force field as in "
                      "Table 1 of Morin et al. 2015 ('9.81, 0, 0': the "
                      "tissue's weight, sideways).");
    prm.declare_entry(
      "Craniotomy",
      "",
      Patterns::Anything(),
      "An opening of the skull: 'sphere: x, y, z, r', 'cylinder: x, y, "
      "z, ax, ay, az, r' (centre, axis direction and radius in the mesh's "
      "length unit; the cylinder is unbounded along its axis) or 'surface: "
      "FILE' (the inside of a closed, outward-oriented surface, .off, .stl "
      "or .obj, in the mesh's length unit, e.g. drawn over the skull in a "
      "segmentation tool). Surface "
      "nodes of the contact labels inside it lose their contact with the "
      "skull (tissue may bulge through), and the pressure faces inside it "
      "(by their centre, mesh geometry) are at atmospheric pressure: they "
      "lose the uniform surface pressure (after Surface pressure). Empty: "
      "no craniotomy.");
    prm.leave_subsection();
  }

  void
  ScenarioParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scenario");
    enabled = prm.get_bool("Enabled");
    rotation_degrees =
      parse_vector(prm.get("Gravity rotation"), "Scenario/Gravity rotation");
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(rotation_degrees[d]) > max_angle_degrees)
        throw InputError("",
                         "Scenario/Gravity rotation",
                         number_text(rotation_degrees[d]) +
                           " degrees; expected angles in degrees between "
                           "-360 and 360");
    const std::string level = Utilities::trim(prm.get("Fluid level"));
    has_fluid_level         = !level.empty();
    if (has_fluid_level)
      fluid_level = Point<3>(parse_vector(level, "Scenario/Fluid level"));
    const std::string pressure_text =
      Utilities::trim(prm.get("Surface pressure"));
    has_pressure = !pressure_text.empty();
    if (has_pressure)
      {
        try
          {
            pressure = parse_number("Scenario/Surface pressure", pressure_text);
          }
        catch (const InputError &)
          {
            throw InputError("",
                             "Scenario/Surface pressure",
                             "'" + pressure_text +
                               "' is not a number; expected a pressure in "
                               "Pa or nothing (unchanged)");
          }
      }
    tissue_acceleration =
      parse_vector(prm.get("Tissue body force"), "Scenario/Tissue body force");
    craniotomy = parse_region(prm.get("Craniotomy"), "Scenario/Craniotomy");
    prm.leave_subsection();
  }

  void
  ScenarioParameters::read_surfaces()
  {
    if (craniotomy.shape != Region::Shape::surface)
      return;
    try
      {
        const auto surface = std::make_shared<const Obstacle>(craniotomy.file,
                                                              craniotomy.unit,
                                                              /*inside=*/true);
        craniotomy.inside  = std::make_shared<const Region::InsideTest>(
          [surface](const Point<3> &x) { return surface->gap(x).gap >= 0; });
      }
    catch (const InputError &e)
      {
        throw InputError(craniotomy.file, "Scenario/Craniotomy", e.message);
      }
  }
} // namespace RestShape
