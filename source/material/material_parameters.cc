// The parameters of subsection Materials.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/material/law_registry.h>
#include <restshape/material/material_parameters.h>

#include <cmath>
#include <cstdlib>

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

  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    youngs_modulus = LabelValues::parse(prm.get("Young's modulus"),
                                        "Materials/Young's modulus");
    poissons_ratio = LabelValues::parse(prm.get("Poisson's ratio"),
                                        "Materials/Poisson's ratio");
    density = LabelValues::parse(prm.get("Density"), "Materials/Density");
    law     = prm.get("Material law");
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
    for (const auto &[label, rho] : density.listed())
      if (!(rho >= 0 && rho <= max_density))
        throw InputError("",
                         "Materials/Density",
                         "rho = " + number_text(rho) + " kg/m^3" +
                           where(density, label) + "; expected 0 <= rho <= " +
                           number_text(max_density) + " kg/m^3");
  }
} // namespace RestShape
