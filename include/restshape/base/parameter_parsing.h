// What the parameter structs of every part share: the parsing of
// vectors and length units, and the parameters that name labels.
#ifndef restshape_base_parameter_parsing_h
#define restshape_base_parameter_parsing_h

#include <deal.II/base/tensor.h>

#include <string>

namespace RestShape
{
  /// Parse a length unit name ("mm" or "m") into metres per unit.
  double
  length_unit_in_metres(const std::string &name, const std::string &parameter);

  /// Parse "x, y, z" (three finite numbers); InputError naming @p parameter.
  dealii::Tensor<1, 3>
  parse_vector(const std::string &text, const std::string &parameter);

  /// A parameter that names labels.
  struct LabelListEntry
  {
    std::string section, entry;
    /// A list of label:value (a lone value is a value for all labels).
    bool values;
  };
} // namespace RestShape

#endif
