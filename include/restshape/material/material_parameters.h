// Subsection "Materials": the moduli, densities and laws by label.
#ifndef restshape_material_material_parameters_h
#define restshape_material_material_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/label_values.h>

#include <map>
#include <string>
#include <vector>

namespace RestShape
{
  struct MaterialParameters
  {
    LabelValues youngs_modulus; // Pa
    LabelValues poissons_ratio; // -
    LabelValues density;        // kg/m^3
    /// Materials/Shear modulus and Bulk modulus (Pa), empty if not given:
    /// where a label has them, they replace E and nu (with only the bulk
    /// modulus, nu follows from E and K).
    LabelValues shear_modulus, bulk_modulus;
    /// Materials/Material law as written: a law's name, or 'label:name'
    /// list (parsed against the laws by MaterialTable).
    std::string law = "corotational";
    /// The laws' own parameters (material/law_registry.h), by name.
    std::map<std::string, LabelValues> law_values;

    /// E (Pa) and nu of @p label, from whichever moduli it was given.
    double
    youngs_modulus_of(const Label label) const;
    double
    poissons_ratio_of(const Label label) const;
    /// Every Poisson's ratio the parameters give (for the choice of the
    /// formulation before the mesh is read).
    std::vector<double>
    listed_poissons_ratios() const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
