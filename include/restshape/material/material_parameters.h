// Subsection "Materials": the moduli, densities and laws by label.
#ifndef restshape_material_material_parameters_h
#define restshape_material_material_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/label_values.h>

#include <map>
#include <string>

namespace RestShape
{
  struct MaterialParameters
  {
    LabelValues youngs_modulus; // Pa
    LabelValues poissons_ratio; // -
    LabelValues density;        // kg/m^3
    /// Materials/Material law as written: a law's name, or 'label:name'
    /// list (parsed against the laws by MaterialTable).
    std::string law = "corotational";
    /// The laws' own parameters (material/law_registry.h), by name.
    std::map<std::string, LabelValues> law_values;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
