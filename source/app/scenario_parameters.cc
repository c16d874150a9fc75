// The parameters of subsection Scenario.
#include <deal.II/base/utilities.h>

#include <restshape/app/scenario_parameters.h>
#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/contact/obstacle.h>
#include <restshape/loads/load_registry.h>

#include <algorithm>
#include <cmath>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Largest rotation angle accepted, in degrees.
    constexpr double max_angle_degrees  = 360;
    constexpr double radians_per_degree = M_PI / 180.;
    /// Sines and cosines below this are zero.
    constexpr double round_off = 1e-15;

    /// The rotation by @p degrees about x, then y, then z.
    Tensor<2, 3>
    rotation(const Tensor<1, 3> &degrees)
    {
      Tensor<2, 3> R = unit_symmetric_tensor<3>();
      for (unsigned int axis = 0; axis < 3; ++axis)
        {
          const double a = degrees[axis] * radians_per_degree;
          // Exact at multiples of 90 degrees (cos 90 = 6e-17 otherwise).
          const auto snap = [](const double x) {
            return std::abs(x) < round_off ? 0. : x;
          };
          const double       c = snap(std::cos(a)), s = snap(std::sin(a));
          const unsigned int i = (axis + 1) % 3, j = (axis + 2) % 3;
          Tensor<2, 3>       Ra = unit_symmetric_tensor<3>();
          Ra[i][i]              = c;
          Ra[i][j]              = -s;
          Ra[j][i]              = s;
          Ra[j][j]              = c;
          R                     = Ra * R;
        }
      return R;
    }

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
      "Craniotomy",
      "",
      Patterns::Anything(),
      "An opening of the skull: 'sphere: x, y, z, r', 'cylinder: x, y, "
      "z, ax, ay, az, r' (centre, axis direction and radius in the mesh's "
      "length unit; the cylinder is unbounded along its axis), 'box: x0, "
      "y0, z0, x1, y1, z1' (two opposite corners) or 'surface: "
      "FILE' (the inside of a closed, outward-oriented surface, .off, .stl "
      "or .obj, in the mesh's length unit, e.g. drawn over the skull in a "
      "segmentation tool). Surface "
      "nodes of the contact labels inside it lose their contact with the "
      "skull (tissue may bulge through), and the pressure faces inside it "
      "(by their centre, mesh geometry) are at atmospheric pressure: they "
      "lose the uniform surface pressure (after Surface pressure). Empty: "
      "no craniotomy.");
    prm.declare_entry(
      "Load scale",
      "",
      Patterns::Anything(),
      "Loads scaled by name after the other changes: 'NAME: factor, NAME: "
      "factor' (dimensionless factors; the names are those of the load "
      "terms' loads, doc/parameters.md, \"Load terms\": e.g. 'Surface "
      "traction: 0' takes a retractor away, 'Gravity: 0.5' halves the "
      "buoyed weight). Empty: none.");
    // The entries of the load terms (load_registry.h).
    for (const ScenarioEntry &e : load_scenario_entries())
      prm.declare_entry(e.name, e.default_value, Patterns::Anything(), e.help);
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
                                       const std::string &scenario_name,
                                       const double       length_unit)
  {
    name = scenario_name;
    prm.enter_subsection(section());
    enabled                 = prm.get_bool("Enabled");
    change.rotation_degrees = parse_vector(prm.get("Gravity rotation"),
                                           section() + "/Gravity rotation");
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(change.rotation_degrees[d]) > max_angle_degrees)
        throw InputError("",
                         section() + "/Gravity rotation",
                         number_text(change.rotation_degrees[d]) +
                           " degrees; expected angles in degrees between "
                           "-360 and 360");
    change.rotation         = rotation(change.rotation_degrees);
    change.turned           = change.rotation_degrees.norm_square() > 0;
    const std::string level = Utilities::trim(prm.get("Fluid level"));
    change.has_fluid_level  = !level.empty();
    if (change.has_fluid_level)
      change.fluid_level =
        Point<3>(length_unit * parse_vector(level, section() + "/Fluid level"));
    change.opening =
      parse_region(prm.get("Craniotomy"), section() + "/Craniotomy");
    change.opening.scale(length_unit);
    for (const ScenarioEntry &e : load_scenario_entries())
      parse_entry(prm, e);
    parse_scale(prm.get("Load scale"));
    prm.leave_subsection();
  }

  void
  ScenarioParameters::parse_entry(ParameterHandler &prm, const ScenarioEntry &e)
  {
    const std::string text = Utilities::trim(prm.get(e.name));
    if (text.empty())
      return;
    const std::string parameter = section() + "/" + e.name;
    if (e.n_values == 3)
      {
        const Tensor<1, 3> v  = parse_vector(text, parameter);
        change.values[e.name] = {v[0], v[1], v[2]};
        return;
      }
    try
      {
        change.values[e.name] = {parse_number(parameter, text)};
      }
    catch (const InputError &)
      {
        throw InputError("",
                         parameter,
                         "'" + text + "' is not a number; expected " + e.help);
      }
  }

  void
  ScenarioParameters::parse_scale(const std::string &text)
  {
    const std::string              parameter = section() + "/Load scale";
    const std::vector<std::string> names     = load_names();
    for (const std::string &item : Utilities::split_string_list(text, ','))
      {
        const auto        colon = item.rfind(':');
        const std::string load  = Utilities::trim(
          item.substr(0, colon == std::string::npos ? 0 : colon));
        if (colon == std::string::npos ||
            std::find(names.begin(), names.end(), load) == names.end())
          {
            std::string known;
            for (const std::string &n : names)
              known += (known.empty() ? "" : ", ") + n;
            throw InputError("",
                             parameter,
                             "'" + item +
                               "': expected 'NAME: factor' with "
                               "NAME one of " +
                               known);
          }
        scale[load] = parse_number(parameter, item.substr(colon + 1));
      }
  }

  void
  ScenarioParameters::read_surfaces()
  {
    Region &craniotomy = change.opening;
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
  ScenarioParameters::check(const EnvironmentParameters &loads,
                            const bool                   inverse_enabled) const
  {
    if (!inverse_enabled)
      throw InputError("",
                       section() + "/Enabled",
                       "a scenario starts from the pre-stressed model: set "
                       "Inverse problem/Enabled = true");
    if (change.has_fluid_level && loads.fluid_density == 0)
      throw InputError("",
                       section() + "/Fluid level",
                       "there is no fluid to drain: expected Loads/Fluid "
                       "density > 0 in kg/m^3");
  }
} // namespace RestShape
