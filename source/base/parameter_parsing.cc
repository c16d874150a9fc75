#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>

namespace RestShape
{
  dealii::Tensor<1, 3>
  parse_vector(const std::string &text, const std::string &parameter)
  {
    const std::array<double, 3> v = parse_triple(parameter, text);
    return dealii::Tensor<1, 3>({v[0], v[1], v[2]});
  }

  double
  length_unit_in_metres(const std::string &name, const std::string &parameter)
  {
    if (name == "mm")
      return 1e-3;
    if (name == "m")
      return 1.0;
    throw InputError("",
                     parameter,
                     "unknown length unit '" + name + "'; expected mm or m");
  }
} // namespace RestShape
