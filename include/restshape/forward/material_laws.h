// The material laws by name: Materials/Material law chooses one per label.
#ifndef restshape_forward_material_laws_h
#define restshape_forward_material_laws_h

#include <restshape/forward/material_law.h>

#include <memory>
#include <string>
#include <vector>

namespace RestShape
{
  /// The names of the laws, in the order of registration.
  std::vector<std::string>
  material_law_names();

  /// The position of @p name in material_law_names() (surrounding blanks
  /// ignored); throws InputError naming @p parameter and the laws if there
  /// is no such law.
  std::size_t
  material_law_index(const std::string &name, const std::string &parameter);

  /// A new law of that name with @p parameters.
  std::unique_ptr<MaterialLaw>
  create_material_law(const std::string &name, const LawParameters &parameters);
} // namespace RestShape

#endif
