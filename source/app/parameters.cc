#include <restshape/app/parameters.h>
#include <restshape/base/input_error.h>
#include <restshape/forward/registered_parameters.h>
#include <restshape/loads/load_registry.h>

#include <algorithm>

namespace RestShape
{
  namespace
  {
    const std::vector<LabelListEntry> label_list_entries = {
      {"Materials", "Young's modulus", true},
      {"Materials", "Poisson's ratio", true},
      {"Materials", "Density", true},
      {"Materials", "Material law", true},
      {"Boundary conditions", "Fixed labels", false},
      {"Contact", "Contact labels", false}};

    /// Every parameter that names labels: the parts' and those the
    /// registered laws and load terms declare.
    std::vector<LabelListEntry>
    all_label_entries()
    {
      std::vector<LabelListEntry>       entries = label_list_entries;
      const std::vector<LabelListEntry> more    = registered_label_entries();
      entries.insert(entries.end(), more.begin(), more.end());
      return entries;
    }

    /// Throws InputError if @p scenario gives a load term's entry whose
    /// scene parameter (ScenarioEntry::needs) is empty.
    void
    check_needs(dealii::ParameterHandler &prm,
                const ScenarioParameters &scenario)
    {
      for (const ScenarioEntry &e : load_scenario_entries())
        {
          if (e.needs.empty() || !scenario.change.has(e.name))
            continue;
          const auto        slash   = e.needs.rfind('/');
          const std::string section = e.needs.substr(0, slash);
          prm.enter_subsection(section);
          const bool empty =
            dealii::Utilities::trim(prm.get(e.needs.substr(slash + 1))).empty();
          prm.leave_subsection();
          if (empty)
            throw InputError("",
                             scenario.section() + "/" + e.name,
                             "the scene leaves " + e.needs +
                               " empty, so this entry has nothing to "
                               "change; expected " +
                               e.needs + " set for the scene too");
        }
    }
  } // namespace

  using dealii::ParameterHandler;

  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    MeshParameters::declare_parameters(prm);
    ForwardParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    VerificationParameters::declare_parameters(prm);
    RefinementParameters::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    InverseParameters::declare_parameters(prm);
    ScenarioParameters::declare_parameters(prm);
    declare_registered_parameters(prm);
  }

  void
  Parameters::parse_parameters(ParameterHandler               &prm,
                               const std::vector<std::string> &scenario_names)
  {
    mesh.parse_parameters(prm);
    forward.parse_parameters(prm, mesh.length_unit);
    parse_registered_parameters(prm, forward, mesh.length_unit);
    double max_poissons_ratio = -1;
    for (const double nu : forward.materials.listed_poissons_ratios())
      max_poissons_ratio = std::max(max_poissons_ratio, nu);
    forward.discretization.resolve_formulation(max_poissons_ratio,
                                               mesh.cell_type ==
                                                 CellType::tetrahedra);
    output.parse_parameters(prm);
    verification.parse_parameters(prm);
    refinement.parse_parameters(prm);
    contact.parse_parameters(prm);
    inverse.parse_parameters(prm);
    // The scenarios' fluid levels are given in the mesh's length unit.
    std::vector<std::string> names = {""};
    names.insert(names.end(), scenario_names.begin(), scenario_names.end());
    for (const std::string &name : names)
      {
        ScenarioParameters scenario;
        scenario.parse_parameters(prm, name, mesh.length_unit);
        if (!scenario.enabled)
          continue;
        scenario.read_surfaces();
        scenario.check(forward.environment, inverse.enabled);
        check_needs(prm, scenario);
        // What a scenario sets where the scene has none (a pressure: its
        // follower tangent is then not symmetric from the start).
        for (const auto &[entry, values] : scenario.change.values)
          for (const double v : values)
            if (v != 0)
              forward.set_later.insert(entry);
        scenarios.push_back(scenario);
      }
    for (const LabelListEntry &e : all_label_entries())
      {
        prm.enter_subsection(e.section);
        label_lists.push_back(
          {e.section + "/" + e.entry, prm.get(e.entry), e.values});
        prm.leave_subsection();
      }
    if (inverse.skull_load_share > 0 && contact.obstacle_file.empty())
      throw InputError("",
                       "Inverse problem/Skull load share",
                       "there is no obstacle to carry a load: expected "
                       "Contact/Obstacle file, or a share of 0");
  }

  void
  Parameters::replace_label_names(ParameterHandler &prm,
                                  const LabelNames &names)
  {
    for (const LabelListEntry &e : all_label_entries())
      {
        prm.enter_subsection(e.section);
        prm.set(e.entry,
                RestShape::replace_label_names(prm.get(e.entry),
                                               e.section + "/" + e.entry,
                                               names,
                                               e.values));
        prm.leave_subsection();
      }
  }
} // namespace RestShape
