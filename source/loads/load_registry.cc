#include <restshape/loads/body_force.h>
#include <restshape/loads/elastic_support.h>
#include <restshape/loads/environment_parameters.h>
#include <restshape/loads/load_registry.h>
#include <restshape/loads/surface_pressure.h>
#include <restshape/loads/surface_traction.h>
#include <restshape/loads/ventricular_pressure.h>

namespace RestShape
{
  const std::vector<LoadTermInfo> &
  load_term_registry()
  {
    // A cavity's own pressure before the surface pressure: it claims the
    // cavity walls.
    static const std::vector<LoadTermInfo> terms = {BodyForce::info(),
                                                    VentricularPressure::info(),
                                                    SurfacePressure::info(),
                                                    ElasticSupport::info(),
                                                    SurfaceTraction::info()};
    return terms;
  }

  void
  declare_load_term_parameters(dealii::ParameterHandler &prm)
  {
    EnvironmentParameters::declare_parameters(prm);
    for (const LoadTermInfo &term : load_term_registry())
      term.declare(prm);
  }

  std::vector<LabelListEntry>
  load_term_label_entries()
  {
    std::vector<LabelListEntry> entries;
    for (const LoadTermInfo &term : load_term_registry())
      entries.insert(entries.end(), term.labels.begin(), term.labels.end());
    return entries;
  }

  std::vector<LoadTermFactory>
  parse_load_terms(dealii::ParameterHandler &prm, const double length_unit)
  {
    std::vector<LoadTermFactory> factories;
    for (const LoadTermInfo &term : load_term_registry())
      if (LoadTermFactory make = term.parse(prm, length_unit))
        factories.push_back(std::move(make));
    return factories;
  }

  std::vector<ScenarioEntry>
  load_scenario_entries()
  {
    std::vector<ScenarioEntry> entries;
    for (const LoadTermInfo &term : load_term_registry())
      entries.insert(entries.end(),
                     term.scenario_entries.begin(),
                     term.scenario_entries.end());
    return entries;
  }

  std::vector<std::string>
  load_names()
  {
    std::vector<std::string> names;
    for (const LoadTermInfo &term : load_term_registry())
      names.insert(names.end(), term.loads.begin(), term.loads.end());
    return names;
  }

  std::string
  load_terms_reference()
  {
    std::string text;
    for (const LoadTermInfo &term : load_term_registry())
      {
        text += "### " + term.name + "\n\n" + term.description + "\n";
        if (!term.loads.empty())
          {
            text += "\nIts loads (Scenario/Load scale):";
            for (const std::string &name : term.loads)
              text += " `" + name + "`";
            text += ".\n";
          }
        for (const ScenarioEntry &e : term.scenario_entries)
          text += "\n- Scenario entry `" + e.name + "`: " + e.help + "\n";
        text += "\n";
      }
    return text;
  }
} // namespace RestShape
