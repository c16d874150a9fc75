#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/material/corotational_law.h>
#include <restshape/material/law_registry.h>
#include <restshape/material/neo_hookean_law.h>
#include <restshape/material/ogden_law.h>

#include <functional>
#include <utility>

namespace RestShape
{
  namespace
  {
    using Factory =
      std::function<std::unique_ptr<MaterialLaw>(const LawParameters &)>;

    template <typename Law>
    Factory
    factory()
    {
      return [](const LawParameters &p) { return std::make_unique<Law>(p); };
    }

    /// What the registry knows of a law: its name (as Materials/Material
    /// law takes it), how to make it, and its own parameters.
    struct Registration
    {
      std::string               name;
      Factory                   make;
      std::vector<LawParameter> parameters = {};
    };

    /// Every law. A new law is one class and one line here.
    const std::vector<Registration> &
    registry()
    {
      static const std::vector<Registration> laws = {
        {"corotational", factory<CorotationalLaw>()},
        {"neo-Hookean", factory<NeoHookeanLaw>()},
        {"Ogden", factory<OgdenLaw>(), OgdenLaw::parameters()}};
      return laws;
    }

    /// " for label 3", " (all labels)" or " (the default '*')".
    std::string
    where(const LabelValues &values, const Label label)
    {
      if (label != dealii::numbers::invalid_material_id)
        return " for label " + std::to_string(label);
      return values.per_label.empty() ? " (all labels)" : " (the default '*')";
    }
  } // namespace

  std::vector<std::string>
  material_law_names()
  {
    std::vector<std::string> names;
    for (const Registration &law : registry())
      names.push_back(law.name);
    return names;
  }

  std::size_t
  material_law_index(const std::string &name, const std::string &parameter)
  {
    const std::string trimmed = dealii::Utilities::trim(name);
    const auto       &laws    = registry();
    for (std::size_t i = 0; i < laws.size(); ++i)
      if (laws[i].name == trimmed)
        return i;
    std::string known;
    for (const Registration &law : laws)
      known += (known.empty() ? "" : ", ") + law.name;
    throw InputError("",
                     parameter,
                     "unknown material law '" + trimmed +
                       "'; expected one of " + known);
  }

  std::vector<std::string>
  material_law_parameter_names(const std::string &name)
  {
    std::vector<std::string> names;
    for (const LawParameter &p :
         registry()[material_law_index(name, "Materials/Material law")]
           .parameters)
      names.push_back(p.name);
    return names;
  }

  void
  declare_material_law_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    for (const Registration &law : registry())
      for (const LawParameter &p : law.parameters)
        prm.declare_entry(p.name,
                          p.default_value,
                          dealii::Patterns::Anything(),
                          p.help);
    prm.leave_subsection();
  }

  std::vector<LabelListEntry>
  material_law_label_entries()
  {
    std::vector<LabelListEntry> entries;
    for (const Registration &law : registry())
      for (const LawParameter &p : law.parameters)
        entries.push_back({"Materials", p.name, true});
    return entries;
  }

  void
  parse_material_law_parameters(dealii::ParameterHandler &prm,
                                MaterialParameters       &materials)
  {
    prm.enter_subsection("Materials");
    for (const Registration &law : registry())
      for (const LawParameter &p : law.parameters)
        materials.law_values[p.name] =
          LabelValues::parse(prm.get(p.name), "Materials/" + p.name);
    prm.leave_subsection();
    for (const Registration &law : registry())
      for (const LawParameter &p : law.parameters)
        {
          const LabelValues &values = materials.law_values[p.name];
          for (const auto &[label, v] : values.listed())
            if (const std::string expected = p.check(v); !expected.empty())
              throw InputError("",
                               "Materials/" + p.name,
                               p.symbol + " = " + number_text(v) +
                                 where(values, label) + "; expected " +
                                 expected);
        }
  }

  std::unique_ptr<MaterialLaw>
  create_material_law(const std::string &name, const LawParameters &parameters)
  {
    return registry()[material_law_index(name, "Materials/Material law")].make(
      parameters);
  }
} // namespace RestShape
