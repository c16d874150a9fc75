#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_names.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace RestShape
{
  double
  parse_number(const std::string &option, const std::string &text)
  {
    const std::string trimmed = dealii::Utilities::trim(text);
    // strtod, not stod: a number below the smallest normal double (1e-308)
    // is a number (it underflows towards 0); only overflow is refused.
    char        *end  = nullptr;
    const double x    = std::strtod(trimmed.c_str(), &end);
    std::size_t  used = end - trimmed.c_str();
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

  namespace
  {
    std::string
    option_list(const std::set<std::string> &names)
    {
      std::string list;
      for (const std::string &n : names)
        list += (list.empty() ? "" : ", ") + n;
      return list;
    }
  } // namespace

  ToolOptions::ToolOptions(const int                       argc,
                           char                          **argv,
                           const std::vector<std::string> &options,
                           const std::vector<std::string> &flags)
  {
    const std::set<std::string> with_value(options.begin(), options.end());
    const std::set<std::string> without(flags.begin(), flags.end());
    std::set<std::string>       all_names = with_value;
    all_names.insert(without.begin(), without.end());
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          help_given = true;
        else if (arg == "--version")
          version_given = true;
        else if (without.count(arg))
          set_flags.insert(arg);
        else if (!with_value.count(arg))
          throw InputError("",
                           arg,
                           "unknown option" +
                             did_you_mean(nearest_names(arg, all_names)) +
                             " (options: " + option_list(all_names) + ")");
        else if (i + 1 >= argc)
          throw InputError("", arg, "missing value after the option");
        else
          values[arg].push_back(argv[++i]);
      }
  }

  bool
  ToolOptions::help() const
  {
    return help_given;
  }

  bool
  ToolOptions::version() const
  {
    return version_given;
  }

  bool
  ToolOptions::given(const std::string &option) const
  {
    return values.count(option) > 0 || set_flags.count(option) > 0;
  }

  std::string
  ToolOptions::text(const std::string &option,
                    const std::string &fallback) const
  {
    const auto it = values.find(option);
    return it == values.end() ? fallback : it->second.back();
  }

  std::string
  ToolOptions::required(const std::string &option,
                        const std::string &expected) const
  {
    if (!values.count(option))
      throw InputError("", option, "not given; expected " + expected);
    return text(option);
  }

  std::vector<std::string>
  ToolOptions::all(const std::string &option) const
  {
    const auto it = values.find(option);
    return it == values.end() ? std::vector<std::string>() : it->second;
  }

  double
  ToolOptions::number(const std::string &option, const double fallback) const
  {
    return given(option) ? parse_number(option, text(option)) : fallback;
  }

  double
  ToolOptions::positive(const std::string &option, const double fallback) const
  {
    return given(option) ? parse_positive(option, text(option)) : fallback;
  }

  double
  ToolOptions::non_negative(const std::string &option,
                            const double       fallback) const
  {
    const double x = number(option, fallback);
    if (x < 0)
      throw InputError("",
                       option,
                       "expected a number >= 0, got '" + text(option) + "'");
    return x;
  }

  long
  ToolOptions::integer(const std::string &option,
                       const long         fallback,
                       const long         min,
                       const long         max) const
  {
    if (!given(option))
      return fallback;
    const double x = parse_number(option, text(option));
    if (x != std::floor(x) || x < min || x > max)
      throw InputError("",
                       option,
                       "expected a whole number from " + std::to_string(min) +
                         " to " + std::to_string(max) + ", got '" +
                         text(option) + "'");
    return static_cast<long>(x);
  }

  std::array<double, 3>
  ToolOptions::triple(const std::string           &option,
                      const std::array<double, 3> &fallback) const
  {
    return given(option) ? parse_triple(option, text(option)) : fallback;
  }

  std::string
  ToolOptions::choice(const std::string              &option,
                      const std::string              &fallback,
                      const std::vector<std::string> &choices) const
  {
    const std::string value = text(option, fallback);
    if (std::find(choices.begin(), choices.end(), value) == choices.end())
      throw InputError("",
                       option,
                       "got '" + value + "'; expected one of " +
                         option_list({choices.begin(), choices.end()}));
    return value;
  }
} // namespace RestShape
