// The parameters of subsection Materials.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/material/law_registry.h>
#include <restshape/material/material_parameters.h>

#include <cmath>
#include <cstdlib>
#include <set>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    prm.declare_entry("Young's modulus",
                      "1500",
                      Patterns::Anything(),
                      "Young's modulus in Pa: one value for all labels, or "
                      "'label:value, label:value' with every label of the "
                      "mesh given a value; a label may be a range "
                      "('1-90:1500') and '*:value' gives every label not "
                      "listed. Must be > 0.");
    prm.declare_entry("Poisson's ratio",
                      "0.45",
                      Patterns::Anything(),
                      "Poisson's ratio, in (-1, 0.5): one value or "
                      "'label:value' list (ranges and '*' as for Young's "
                      "modulus).");
    prm.declare_entry("Shear modulus",
                      "",
                      Patterns::Anything(),
                      "Shear modulus mu in Pa, with Bulk modulus instead of "
                      "Young's modulus and Poisson's ratio (E = 9 K mu / (3 "
                      "K + mu), nu = (3 K - 2 mu) / (2 (3 K + mu))): one value "
                      "or 'label:value' list (ranges and '*' as for Young's "
                      "modulus). Empty: not used. A label given a shear "
                      "modulus needs a bulk modulus.");
    prm.declare_entry("Bulk modulus",
                      "",
                      Patterns::Anything(),
                      "Bulk modulus K in Pa, the volumetric stiffness (in vivo "
                      "brain tissue about 1.5e5 Pa against a shear modulus "
                      "below 1e3 Pa): one value or 'label:value' list. Where "
                      "a label has one, it replaces Poisson's ratio: with a "
                      "shear modulus as above, else from Young's modulus, nu "
                      "= (3 K - E) / (6 K) (K > E / 9). Empty: not used.");
    prm.declare_entry("Density",
                      "1040",
                      Patterns::Anything(),
                      "Density in kg/m^3 of the tissue as imaged (the mass "
                      "of every cell is taken from the mesh geometry and "
                      "kept when the rest shape changes): one value or "
                      "'label:value' list (ranges and '*' as for Young's "
                      "modulus). Must be >= 0.");
    prm.declare_entry(
      "Material law",
      "corotational",
      Patterns::Anything(),
      "The hyperelastic law of the tissue: one name for all labels or a "
      "'label:name' list (ranges and '*' as for Young's modulus). " +
        material_law_help() +
        ". All take mu and lambda from Young's modulus and Poisson's ratio "
        "(mu = E / (2 (1 + nu))), and agree at small strain.");
    prm.leave_subsection();
  }

  namespace
  {
    /// Moduli beyond any material are input errors.
    void
    check_moduli(const LabelValues &values, const std::string &parameter)
    {
      constexpr double least = 1e-3, largest = 1e15; // Pa, as for E
      for (const auto &[label, v] : values.listed())
        if (!(v >= least && v <= largest))
          throw InputError("",
                           parameter,
                           number_text(v) + " Pa" +
                             (label == dealii::numbers::invalid_material_id ?
                                std::string() :
                                " for label " + std::to_string(label)) +
                             "; expected " + number_text(least) +
                             " Pa <= value <= " + number_text(largest) + " Pa");
    }

    bool
    given(const LabelValues &values, const Label label)
    {
      return !values.parameter.empty() && values.has(label);
    }
  } // namespace

  double
  MaterialParameters::youngs_modulus_of(const Label label) const
  {
    if (!given(shear_modulus, label))
      return youngs_modulus(label);
    if (!given(bulk_modulus, label))
      throw InputError("",
                       "Materials/Bulk modulus",
                       "label " + std::to_string(label) +
                         " has a shear modulus but no bulk modulus; expected "
                         "both (or Young's modulus and Poisson's ratio)");
    const double mu = shear_modulus(label), K = bulk_modulus(label);
    return 9 * K * mu / (3 * K + mu);
  }

  double
  MaterialParameters::poissons_ratio_of(const Label label) const
  {
    if (!given(bulk_modulus, label))
      return poissons_ratio(label);
    const double K  = bulk_modulus(label);
    const double E  = youngs_modulus_of(label);
    const double nu = (3 * K - E) / (6 * K);
    if (!(nu > -1 && nu < 0.5))
      throw InputError("",
                       "Materials/Bulk modulus",
                       "K = " + number_text(K) + " Pa for label " +
                         std::to_string(label) + " with E = " + number_text(E) +
                         " Pa gives nu = " + number_text(nu) +
                         "; expected K > E / 9 (nu > -1)");
    return nu;
  }

  std::vector<double>
  MaterialParameters::listed_poissons_ratios() const
  {
    std::vector<double> result;
    if (bulk_modulus.parameter.empty())
      {
        for (const auto &[label, nu] : poissons_ratio.listed())
          result.push_back(nu);
        return result;
      }
    // The labels any modulus names, and one that only defaults cover.
    std::set<Label> labels = {dealii::numbers::invalid_material_id - 1};
    for (const LabelValues *v :
         {&youngs_modulus, &poissons_ratio, &shear_modulus, &bulk_modulus})
      for (const auto &[label, x] : v->per_label)
        labels.insert(label);
    for (const Label label : labels)
      try
        {
          result.push_back(poissons_ratio_of(label));
        }
      catch (const InputError &)
        {
          // A label without values: the mesh's labels are checked later.
        }
    return result;
  }

  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    youngs_modulus = LabelValues::parse(prm.get("Young's modulus"),
                                        "Materials/Young's modulus");
    poissons_ratio = LabelValues::parse(prm.get("Poisson's ratio"),
                                        "Materials/Poisson's ratio");
    density = LabelValues::parse(prm.get("Density"), "Materials/Density");
    const auto optional = [&](const std::string &name) {
      const std::string text = dealii::Utilities::trim(prm.get(name));
      return text.empty() ? LabelValues() :
                            LabelValues::parse(text, "Materials/" + name);
    };
    shear_modulus = optional("Shear modulus");
    bulk_modulus  = optional("Bulk modulus");
    law           = prm.get("Material law");
    prm.leave_subsection();

    const auto where = [](const LabelValues &values, const Label l) {
      if (l != dealii::numbers::invalid_material_id)
        return " for label " + std::to_string(l);
      return std::string(values.per_label.empty() ? " (all labels)" :
                                                    " (the default '*')");
    };
    // Beyond any material (diamond: 1.2e12 Pa; the softest tissues: 1e2):
    // such values overflow the stiffness matrix or vanish in it.
    constexpr double min_youngs_modulus = 1e-3, max_youngs_modulus = 1e15;
    constexpr double max_density = 1e6; // kg/m^3 (osmium: 22,600)
    for (const auto &[label, E] : youngs_modulus.listed())
      if (!(E >= min_youngs_modulus && E <= max_youngs_modulus))
        throw InputError("",
                         "Materials/Young's modulus",
                         "E = " + number_text(E) + " Pa" +
                           where(youngs_modulus, label) + "; expected " +
                           number_text(min_youngs_modulus) + " Pa <= E <= " +
                           number_text(max_youngs_modulus) + " Pa");
    for (const auto &[label, nu] : poissons_ratio.listed())
      if (!(nu > -1 && nu < 0.5))
        throw InputError("",
                         "Materials/Poisson's ratio",
                         "nu = " + number_text(nu) +
                           where(poissons_ratio, label) +
                           "; expected -1 < nu < 0.5");
    check_moduli(shear_modulus, "Materials/Shear modulus");
    check_moduli(bulk_modulus, "Materials/Bulk modulus");
    for (const auto &[label, rho] : density.listed())
      if (!(rho >= 0 && rho <= max_density))
        throw InputError("",
                         "Materials/Density",
                         "rho = " + number_text(rho) + " kg/m^3" +
                           where(density, label) + "; expected 0 <= rho <= " +
                           number_text(max_density) + " kg/m^3");
  }
} // namespace RestShape
