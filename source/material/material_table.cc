#include <restshape/base/input_error.h>
#include <restshape/material/law_registry.h>
#include <restshape/material/material_table.h>

#include <cmath>

namespace RestShape
{
  using namespace dealii;

  SymmetricTensor<2, 3>
  cauchy_stress(const Tensor2 &F, const Tensor2 &P)
  {
    return symmetrize(P * transpose(F)) / determinant(F);
  }

  double
  von_mises(const SymmetricTensor<2, 3> &sigma)
  {
    const SymmetricTensor<2, 3> s = deviator(sigma);
    return std::sqrt(1.5 * (s * s));
  }

  MaterialTable::MaterialTable(const MaterialParameters &prm,
                               const std::set<Label>    &labels)
  {
    const std::vector<std::string> law_names = material_law_names();
    const LabelValues              laws      = LabelValues::parse(
      prm.law, "Materials/Material law", [&](const std::string &text) {
        return double(material_law_index(text, "Materials/Material law"));
      });
    for (const Label label : labels)
      {
        Entry e;
        e.E   = prm.youngs_modulus_of(label);
        e.rho = prm.density(label);

        // A label needs a value of the parameters of its own law only.
        const std::string &name = law_names[std::size_t(laws(label))];
        LawParameters      law{e.E, prm.poissons_ratio_of(label), {}};
        for (const std::string &p : material_law_parameter_names(name))
          if (const auto v = prm.law_values.find(p); v != prm.law_values.end())
            law.values[p] = v->second(label);
        e.law          = create_material_law(name, law);
        entries[label] = e;
      }
  }

  const MaterialLaw &
  MaterialTable::law(const Label label) const
  {
    return *entries.at(label).law;
  }

  double
  MaterialTable::density(const Label label) const
  {
    return entries.at(label).rho;
  }

  double
  MaterialTable::youngs_modulus(const Label label) const
  {
    return entries.at(label).E;
  }

  double
  MaterialTable::max_youngs_modulus() const
  {
    double E = 0;
    for (const auto &[label, entry] : entries)
      E = std::max(E, entry.E);
    return E;
  }
} // namespace RestShape
