#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameters.h>

#include <cmath>
#include <cstdlib>

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
      {"Boundary conditions", "Elastic support labels", false},
      {"Loads", "Pressure labels", false},
      {"Contact", "Contact labels", false}};
  } // namespace

  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  dealii::Tensor<1, 3>
  parse_vector(const std::string &text, const std::string &parameter)
  {
    const std::array<double, 3> v = parse_triple(parameter, text);
    return dealii::Tensor<1, 3>({v[0], v[1], v[2]});
  }

  double
  length_unit_in_metres(const std::string &name, const std::string &parameter)
  {
    if (name == "mm")
      return 1e-3;
    if (name == "m")
      return 1.0;
    throw InputError("",
                     parameter,
                     "unknown length unit '" + name + "'; expected mm or m");
  }

  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    MeshParameters::declare_parameters(prm);
    DiscretizationParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    BoundaryParameters::declare_parameters(prm);
    LoadParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    VerificationParameters::declare_parameters(prm);
    RefinementParameters::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    InverseParameters::declare_parameters(prm);
    ScenarioParameters::declare_parameters(prm);
  }

  void
  Parameters::parse_parameters(
    ParameterHandler                  &prm,
    const std::vector<std::string>    &scenario_names,
    const std::vector<LabelListEntry> &more_label_lists)
  {
    mesh.parse_parameters(prm);
    discretization.parse_parameters(prm);
    materials.parse_parameters(prm);
    boundary.parse_parameters(prm);
    loads.parse_parameters(prm);
    solver.parse_parameters(prm);
    output.parse_parameters(prm);
    verification.parse_parameters(prm);
    refinement.parse_parameters(prm);
    contact.parse_parameters(prm);
    inverse.parse_parameters(prm);
    // The fluid levels are given in the mesh's length unit.
    loads.fluid_level *= mesh.length_unit;
    std::vector<std::string> names = {""};
    names.insert(names.end(), scenario_names.begin(), scenario_names.end());
    for (const std::string &name : names)
      {
        ScenarioParameters scenario;
        scenario.parse_parameters(prm, name);
        if (!scenario.enabled)
          continue;
        scenario.fluid_level *= mesh.length_unit;
        scenario.craniotomy.scale(mesh.length_unit);
        scenario.read_surfaces();
        scenario.check(loads, inverse.enabled);
        scenarios.push_back(scenario);
      }
    std::vector<LabelListEntry> entries = label_list_entries;
    entries.insert(entries.end(),
                   more_label_lists.begin(),
                   more_label_lists.end());
    for (const LabelListEntry &e : entries)
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
  Parameters::replace_label_names(
    ParameterHandler                  &prm,
    const LabelNames                  &names,
    const std::vector<LabelListEntry> &more_label_lists)
  {
    std::vector<LabelListEntry> entries = label_list_entries;
    entries.insert(entries.end(),
                   more_label_lists.begin(),
                   more_label_lists.end());
    for (const LabelListEntry &e : entries)
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
