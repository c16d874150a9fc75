#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>

#include <cmath>

namespace RestShape
{
  bool
  wants_help(const int argc, char **argv)
  {
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h")
        return true;
    return false;
  }

  double
  parse_number(const std::string &option, const std::string &text)
  {
    const std::string trimmed = dealii::Utilities::trim(text);
    std::size_t       used    = 0;
    double            x       = 0;
    try
      {
        x = std::stod(trimmed, &used);
      }
    catch (const std::exception &)
      {
        used = 0;
      }
    if (used == 0 || used != trimmed.size() || !std::isfinite(x))
      throw InputError("", option, "'" + trimmed + "' is not a finite number");
    return x;
  }

  double
  parse_positive(const std::string &option, const std::string &text)
  {
    double x = 0;
    try
      {
        x = parse_number(option, text);
      }
    catch (const InputError &)
      {
        x = 0;
      }
    if (!(x > 0))
      throw InputError("",
                       option,
                       "expected a positive number, got '" + text + "'");
    return x;
  }

  std::array<double, 3>
  parse_triple(const std::string &option, const std::string &text)
  {
    const auto items = dealii::Utilities::split_string_list(text, ',');
    if (items.size() != 3)
      throw InputError("",
                       option,
                       "expected three comma-separated numbers, got '" + text +
                         "'");
    return {{parse_number(option, items[0]),
             parse_number(option, items[1]),
             parse_number(option, items[2])}};
  }
} // namespace RestShape
