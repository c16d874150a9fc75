// The parameters of subsection Scenario.
#include <deal.II/base/utilities.h>

#include <restshape/app/scenario_parameters.h>
#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
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
  ScenarioParameters::declare_parameters(ParameterHandler  &prm,
                                         const std::string &name)
  {
    prm.enter_subsection(name.empty() ? "Scenario" : "Scenario " + name);
    prm.declare_entry(
      "Enabled",
      name.empty() ? "false" : "true",
      Patterns::Bool(),
      "After the inverse problem, change the loads as given below and "
      "solve (1) the pre-stressed model, from its equilibrium under the "
      "scene's loads to the changed loads, and (2) the model stress-free in "
      "the same geometry and contact state (the pre-stressed model's "
      "equilibrium), under the change alone. Writes scenario.csv (shift of "
      "every tissue's centroid and its largest nodal shift, both models, "
      "and their ratio) and scenario.vtu (both shift fields). Further "
      "scenarios of the same run: a subsection 'Scenario NAME' each (NAME of "
      "letters, digits, '-' and '_'), with the entries of this one (Enabled "
      "= true by default there), run in the order written, each from the "
      "same equilibrium; they write scenario_NAME.csv and scenario_NAME.vtu "
      "and their summary keys start with scenario_NAME_.");
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
                      "rotated one). With Loads/Fluid load = buoyancy, tissue "
                      "above it (in the mesh geometry) loses its buoyancy; "
                      "with hydrostatic pressure, the pressure faces above it "
                      "are at atmospheric pressure (plus Surface pressure) "
                      "and those below it carry rho_fluid g times their depth "
                      "below it. Empty: no drainage (with hydrostatic "
                      "pressure and a rotation: the free surface turns about "
                      "Loads/Fluid level, or stays above the highest pressure "
                      "face where that is empty).");
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

  std::string
  ScenarioParameters::section() const
  {
    return name.empty() ? "Scenario" : "Scenario " + name;
  }

  std::string
  ScenarioParameters::output_name() const
  {
    return name.empty() ? "scenario" : "scenario_" + name;
  }

  void
  ScenarioParameters::parse_parameters(ParameterHandler  &prm,
                                       const std::string &scenario_name)
  {
    name = scenario_name;
    prm.enter_subsection(section());
    enabled          = prm.get_bool("Enabled");
    rotation_degrees = parse_vector(prm.get("Gravity rotation"),
                                    section() + "/Gravity rotation");
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(rotation_degrees[d]) > max_angle_degrees)
        throw InputError("",
                         section() + "/Gravity rotation",
                         number_text(rotation_degrees[d]) +
                           " degrees; expected angles in degrees between "
                           "-360 and 360");
    const std::string level = Utilities::trim(prm.get("Fluid level"));
    has_fluid_level         = !level.empty();
    if (has_fluid_level)
      fluid_level = Point<3>(parse_vector(level, section() + "/Fluid level"));
    const std::string pressure_text =
      Utilities::trim(prm.get("Surface pressure"));
    has_pressure = !pressure_text.empty();
    if (has_pressure)
      {
        try
          {
            pressure =
              parse_number(section() + "/Surface pressure", pressure_text);
          }
        catch (const InputError &)
          {
            throw InputError("",
                             section() + "/Surface pressure",
                             "'" + pressure_text +
                               "' is not a number; expected a pressure in "
                               "Pa or nothing (unchanged)");
          }
      }
    tissue_acceleration = parse_vector(prm.get("Tissue body force"),
                                       section() + "/Tissue body force");
    craniotomy = parse_region(prm.get("Craniotomy"), section() + "/Craniotomy");
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
        throw InputError(craniotomy.file, section() + "/Craniotomy", e.message);
      }
  }

  void
  ScenarioParameters::check(const LoadParameters &loads,
                            const bool            inverse_enabled) const
  {
    if (!inverse_enabled)
      throw InputError("",
                       section() + "/Enabled",
                       "a scenario starts from the pre-stressed model: set "
                       "Inverse problem/Enabled = true");
    if (has_fluid_level && loads.fluid_density == 0)
      throw InputError("",
                       section() + "/Fluid level",
                       "there is no fluid to drain: expected Loads/Fluid "
                       "density > 0 in kg/m^3");
  }
} // namespace RestShape
