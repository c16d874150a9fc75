// The parameters that the registered material laws (law_registry.h) and
// load terms (load_registry.h) declare themselves, beside those of the part
// structs.
#ifndef restshape_forward_registered_parameters_h
#define restshape_forward_registered_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/parameter_parsing.h>
#include <restshape/forward/forward_parameters.h>

#include <vector>

namespace RestShape
{
  /// Declare them (after Parameters::declare_parameters()).
  void
  declare_registered_parameters(dealii::ParameterHandler &prm);

  /// Those that name labels (for Parameters::replace_label_names() and
  /// Parameters::parse_parameters()).
  std::vector<LabelListEntry>
  registered_label_entries();

  /// Parse them into @p parameters (after ForwardParameters::
  /// parse_parameters()): the laws' values and the load terms the scene
  /// enables; @p length_unit: metres per unit of the mesh. Throws
  /// InputError naming the parameter for a bad value.
  void
  parse_registered_parameters(dealii::ParameterHandler &prm,
                              ForwardParameters        &parameters,
                              const double              length_unit);
} // namespace RestShape

#endif
