#include <deal.II/base/exceptions.h>

#include <restshape/base/input_error.h>

#include <regex>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// Control bytes (NUL, escape sequences, carriage returns) in a file
    /// name or a quoted input reach the terminal as "\xNN", line breaks
    /// and tabs as spaces: an error stays one printable line.
    std::string
    printable(const std::string &text)
    {
      static const char *const hex = "0123456789abcdef";
      std::string              result;
      for (const char c : text)
        {
          const auto byte = static_cast<unsigned char>(c);
          if (c == '\n' || c == '\t')
            result += ' ';
          else if (byte < 0x20 || byte == 0x7f)
            result += std::string("\\x") + hex[byte >> 4] + hex[byte & 0xf];
          else
            result += c;
        }
      return result;
    }

    std::string
    compose(const std::string &file,
            const std::string &parameter,
            const std::string &message)
    {
      std::string text;
      if (!file.empty())
        text += file + ": ";
      if (!parameter.empty())
        text += parameter + ": ";
      return printable(text + message);
    }
  } // namespace

  InputError::InputError(const std::string &file,
                         const std::string &parameter,
                         const std::string &message)
    : std::runtime_error(compose(file, parameter, message))
    , file(file)
    , parameter(parameter)
    , message(message)
  {}

  InputError
  InputError::in_file(const std::string &new_file) const
  {
    return InputError(new_file, parameter, message);
  }

  std::string
  one_line_message(const std::exception &exc)
  {
    std::string text;
    if (const auto *dealii_exc =
          dynamic_cast<const dealii::ExceptionBase *>(&exc))
      {
        std::ostringstream info;
        dealii_exc->print_info(info);
        text = info.str();
        if (text.find_first_not_of(" \n\t") == std::string::npos)
          text = dealii_exc->get_exc_name();
      }
    else
      text = exc.what();

    // Collapse all white space (deal.II indents and wraps its messages).
    std::string result;
    bool        space = false;
    for (const char c : printable(text))
      if (c == '\n' || c == '\t' || c == ' ' || c == '\r')
        space = !result.empty();
      else
        {
          if (space)
            result += ' ';
          result += c;
          space = false;
        }
    // ParameterHandler: "Line <3> of file <scene.prm>: ..." -> "line 3: ...".
    static const std::regex prm_location("Line <([0-9]+)> of file <[^>]*>?:");
    return std::regex_replace(result, prm_location, "line $1:");
  }

  std::string
  number_text(const double value)
  {
    std::ostringstream text;
    text << value;
    return text.str();
  }
} // namespace RestShape
