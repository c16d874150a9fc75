#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/loads/ventricular_pressure.h>

namespace RestShape
{
  using namespace dealii;

  const std::string VentricularPressure::load_name = "Ventricular pressure";

  namespace
  {
    const std::string &name  = VentricularPressure::load_name;
    const std::string  entry = "Loads/" + name;
  } // namespace

  LoadTermInfo
  VentricularPressure::info()
  {
    LoadTermInfo i;
    i.name = name;
    i.description =
      "A uniform pressure on the walls of the mesh's cavities (the "
      "ventricles: surface components that enclose no tissue), apart from "
      "the surface pressure outside; a follower or a dead load as "
      "Loads/Pressure load says. Where it is set, the surface pressure and "
      "the CSF's hydrostatic pressure act on the outer surface alone.";
    i.loads   = {name};
    i.declare = [](ParameterHandler &prm) {
      prm.enter_subsection("Loads");
      prm.declare_entry(
        name,
        "",
        Patterns::Anything(),
        "Uniform pressure in Pa on the walls of the mesh's cavities (the "
        "ventricles), along their inward normal (into the tissue); the "
        "surface pressure then acts on the outer surface only. Empty: the "
        "cavities carry the surface pressure (and the fluid's hydrostatic "
        "pressure) as the outer surface does (CSF that communicates). "
        "Needs a mesh with a cavity.");
      prm.leave_subsection();
    };
    i.parse = [](ParameterHandler &prm, const double) -> LoadTermFactory {
      prm.enter_subsection("Loads");
      const std::string text     = Utilities::trim(prm.get(name));
      const bool        follower = prm.get("Pressure load") == "follower";
      prm.leave_subsection();
      if (text.empty())
        return {};
      Settings s;
      s.pressure = parse_number(entry, text);
      s.follower = follower;
      return [s](const LoadContext &context) {
        return std::make_unique<VentricularPressure>(s, context);
      };
    };
    i.scenario_entries = {
      {name,
       "",
       "The ventricular pressure in Pa after the change (0: drained "
       "ventricles). Empty: unchanged. Needs Loads/Ventricular pressure.",
       1,
       entry}};
    return i;
  }

  VentricularPressure::VentricularPressure(const Settings    &settings,
                                           const LoadContext &context)
    : SurfacePressure(settings,
                      EnvironmentParameters(),
                      context,
                      PressureNames(name),
                      Walls::cavities)
  {
    if (CavityWalls(context.mesh).n_cavities() == 0)
      throw InputError("",
                       entry,
                       "the mesh has no cavity (every surface component "
                       "encloses tissue); expected a mesh with ventricles, "
                       "or the parameter left empty");
    context.claimed_surfaces->insert(cavity_walls_name);
  }
} // namespace RestShape
