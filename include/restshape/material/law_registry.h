// The material laws by name: Materials/Material law chooses one per label.
#ifndef restshape_material_law_registry_h
#define restshape_material_law_registry_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/parameter_parsing.h>
#include <restshape/material/material_law.h>
#include <restshape/material/material_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace RestShape
{
  /// "corotational: ...; neo-Hookean: ...": every law's name and
  /// description, for the help of Materials/Material law.
  std::string
  material_law_help();

  /// The names of the laws, in the order of registration.
  std::vector<std::string>
  material_law_names();

  /// The position of @p name in material_law_names() (surrounding blanks
  /// ignored); throws InputError naming @p parameter and the laws if there
  /// is no such law.
  std::size_t
  material_law_index(const std::string &name, const std::string &parameter);

  /// The parameters the law @p name declares (by name).
  std::vector<std::string>
  material_law_parameter_names(const std::string &name);

  /// Declare, in subsection Materials, the parameters of every law.
  void
  declare_material_law_parameters(dealii::ParameterHandler &prm);

  /// The laws' parameters, each a list of label:value.
  std::vector<LabelListEntry>
  material_law_label_entries();

  /// Parse the laws' parameters into @p materials (law_values); throws
  /// InputError naming the parameter for a value a law does not admit.
  void
  parse_material_law_parameters(dealii::ParameterHandler &prm,
                                MaterialParameters       &materials);

  /// A new law of that name with @p parameters.
  std::unique_ptr<MaterialLaw>
  create_material_law(const std::string &name, const LawParameters &parameters);
} // namespace RestShape

#endif
