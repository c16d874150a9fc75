// Numbers in option values of the companion tools (restshape-mesh,
// -gridgen, ...) and in parameter texts, checked so that a bad value is one
// InputError naming the option or parameter.
#ifndef restshape_command_line_h
#define restshape_command_line_h

#include <array>
#include <string>

namespace RestShape
{
  /// A number; throws InputError naming @p option unless all of @p text is one.
  double
  parse_number(const std::string &option, const std::string &text);

  /// A number > 0.
  double
  parse_positive(const std::string &option, const std::string &text);

  /// Three comma-separated numbers, e.g. "1, 2.5, -3".
  std::array<double, 3>
  parse_triple(const std::string &option, const std::string &text);

  /// Whether the command line asks for help (--help or -h anywhere).
  bool
  wants_help(const int argc, char **argv);
} // namespace RestShape

#endif
