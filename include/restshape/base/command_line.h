// Numbers in option values of the companion tools (restshape-mesh,
// -gridgen, ...) and in parameter texts, checked so that a bad value is one
// InputError naming the option or parameter.
#ifndef restshape_command_line_h
#define restshape_command_line_h

#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

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

  /**
   * The command line of a companion tool: options with a value
   * ("--out FILE"), flags without one ("--flip"), --help/-h and --version.
   * Every option is declared; an unknown option, a missing value or a bad
   * number is an InputError naming the option (with the nearest declared ones).
   * An option given twice keeps its last value; all() returns every one.
   */
  class ToolOptions
  {
  public:
    ToolOptions(const int                       argc,
                char                          **argv,
                const std::vector<std::string> &options,
                const std::vector<std::string> &flags = {});

    /// --help or -h was given (the tool then prints its usage, exit 0).
    bool
    help() const;

    /// --version was given (the tool then prints version_text(), exit 0).
    bool
    version() const;

    bool
    given(const std::string &option) const;

    /// The value; @p fallback when not given.
    std::string
    text(const std::string &option, const std::string &fallback = "") const;

    /// The value, which must be given: else InputError "@p expected".
    std::string
    required(const std::string &option, const std::string &expected) const;

    /// Every value of an option that may be repeated, in order.
    std::vector<std::string>
    all(const std::string &option) const;

    /// A finite number.
    double
    number(const std::string &option, const double fallback) const;

    /// A number > 0.
    double
    positive(const std::string &option, const double fallback) const;

    /// A number >= 0.
    double
    non_negative(const std::string &option, const double fallback) const;

    /// A whole number in [@p min, @p max].
    long
    integer(const std::string &option,
            const long         fallback,
            const long         min,
            const long         max) const;

    /// Three comma-separated numbers.
    std::array<double, 3>
    triple(const std::string           &option,
           const std::array<double, 3> &fallback) const;

    /// One of @p choices.
    std::string
    choice(const std::string              &option,
           const std::string              &fallback,
           const std::vector<std::string> &choices) const;

  private:
    std::map<std::string, std::vector<std::string>> values;
    std::set<std::string>                           set_flags;
    bool                                            help_given    = false;
    bool                                            version_given = false;
  };
} // namespace RestShape

#endif
