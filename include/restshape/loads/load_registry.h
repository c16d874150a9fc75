// The registry of load terms a scene can enable beyond the built-in ones
// (body force, surface pressure, elastic support): each declares its own
// parameters and, from their values, makes its LoadTerm or none.
#ifndef restshape_loads_load_registry_h
#define restshape_loads_load_registry_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/parameter_parsing.h>
#include <restshape/forward/forward_parameters.h>
#include <restshape/loads/load_term.h>

#include <memory>
#include <vector>

namespace RestShape
{
  /// Declare the parameters of every registered load term.
  void
  declare_load_term_parameters(dealii::ParameterHandler &prm);

  /// The parameters of the registered load terms that name labels (for
  /// Parameters::replace_label_names() and parse_parameters()).
  std::vector<LabelListEntry>
  load_term_label_entries();

  /// The terms the values of @p prm enable, ready to be made on a
  /// discretisation. Throws InputError naming the parameter for a bad
  /// value.
  std::vector<LoadTermFactory>
  parse_load_terms(dealii::ParameterHandler &prm);

  /// The terms of @p factories made on @p context.
  std::vector<std::unique_ptr<LoadTerm>>
  create_load_terms(const std::vector<LoadTermFactory> &factories,
                    const LoadContext                  &context);
} // namespace RestShape

#endif
