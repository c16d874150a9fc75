#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/forward/corotational_law.h>
#include <restshape/forward/material_laws.h>
#include <restshape/forward/neo_hookean_law.h>
#include <restshape/forward/ogden_law.h>

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

    /// Every law: its name (as Materials/Material law takes it) and how
    /// to make it. A new law is one file and one line here.
    const std::vector<std::pair<std::string, Factory>> &
    registry()
    {
      static const std::vector<std::pair<std::string, Factory>> laws = {
        {"corotational", factory<CorotationalLaw>()},
        {"neo-Hookean", factory<NeoHookeanLaw>()},
        {"Ogden", factory<OgdenLaw>()}};
      return laws;
    }
  } // namespace

  std::vector<std::string>
  material_law_names()
  {
    std::vector<std::string> names;
    for (const auto &[name, make] : registry())
      names.push_back(name);
    return names;
  }

  std::size_t
  material_law_index(const std::string &name, const std::string &parameter)
  {
    const std::string trimmed = dealii::Utilities::trim(name);
    const auto       &laws    = registry();
    for (std::size_t i = 0; i < laws.size(); ++i)
      if (laws[i].first == trimmed)
        return i;
    std::string known;
    for (const auto &[law, make] : laws)
      known += (known.empty() ? "" : ", ") + law;
    throw InputError("",
                     parameter,
                     "unknown material law '" + trimmed +
                       "'; expected one of " + known);
  }

  std::unique_ptr<MaterialLaw>
  create_material_law(const std::string &name, const LawParameters &parameters)
  {
    return registry()[material_law_index(name, "Materials/Material law")]
      .second(parameters);
  }
} // namespace RestShape
