#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/material/corotational_law.h>
#include <restshape/material/law_registry.h>
#include <restshape/material/mooney_rivlin_law.h>
#include <restshape/material/neo_hookean_law.h>
#include <restshape/material/ogden_law.h>

#include <functional>
#include <utility>

namespace RestShape
{
  namespace
  {
    /// Every law. A new law is one class and one line here.
    const std::vector<LawInfo> &
    registry()
    {
      static const std::vector<LawInfo> laws = {CorotationalLaw::info(),
                                                NeoHookeanLaw::info(),
                                                OgdenLaw::info(),
                                                MooneyRivlinLaw::info()};
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

  std::string
  material_law_help()
  {
    std::string text;
    for (const LawInfo &law : registry())
      text += (text.empty() ? "" : "; ") + law.name + ": " + law.description;
    return text;
  }

  std::vector<std::string>
  material_law_names()
  {
    std::vector<std::string> names;
    for (const LawInfo &law : registry())
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
    for (const LawInfo &law : laws)
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
    for (const LawInfo &law : registry())
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
    for (const LawInfo &law : registry())
      for (const LawParameter &p : law.parameters)
        entries.push_back({"Materials", p.name, true});
    return entries;
  }

  void
  parse_material_law_parameters(dealii::ParameterHandler &prm,
                                MaterialParameters       &materials)
  {
    prm.enter_subsection("Materials");
    for (const LawInfo &law : registry())
      for (const LawParameter &p : law.parameters)
        materials.law_values[p.name] =
          LabelValues::parse(prm.get(p.name), "Materials/" + p.name);
    prm.leave_subsection();
    for (const LawInfo &law : registry())
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
