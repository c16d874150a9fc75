#include <restshape/forward/registered_parameters.h>
#include <restshape/loads/load_registry.h>
#include <restshape/material/law_registry.h>

namespace RestShape
{
  void
  declare_registered_parameters(dealii::ParameterHandler &prm)
  {
    declare_material_law_parameters(prm);
    declare_load_term_parameters(prm);
  }

  std::vector<LabelListEntry>
  registered_label_entries()
  {
    std::vector<LabelListEntry> entries = material_law_label_entries();
    for (const LabelListEntry &e : load_term_label_entries())
      entries.push_back(e);
    return entries;
  }

  void
  parse_registered_parameters(dealii::ParameterHandler &prm,
                              ForwardParameters        &parameters,
                              const double              length_unit)
  {
    parse_material_law_parameters(prm, parameters.materials);
    parameters.load_terms = parse_load_terms(prm, length_unit);
  }
} // namespace RestShape
