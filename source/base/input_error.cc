#include <deal.II/base/exceptions.h>

#include <restshape/base/input_error.h>

#include <limits>
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

    /// deal.II's description of a pattern in words: "[Selection a|b ]" ->
    /// "one of a, b", "[Integer range 1...2147483647 (inclusive)]" -> "an
    /// integer of at least 1", "[Bool]" -> "true or false"; others as
    /// deal.II writes them.
    std::string
    pattern_in_words(const std::string &pattern)
    {
      std::smatch             m;
      static const std::regex selection(R"(Selection (.*?) *)");
      static const std::regex range(
        R"((Integer range|Double) (\S+)\.\.\.(\S+) \(inclusive\))");
      if (std::regex_match(pattern, m, selection))
        return "one of " +
               std::regex_replace(m[1].str(), std::regex(R"(\|)"), ", ");
      if (pattern == "Bool")
        return "true or false";
      if (std::regex_match(pattern, m, range))
        {
          const std::string kind = m[1] == "Double" ? "a number" : "an integer";
          // deal.II's bounds when none is given: MAX_DOUBLE, INT_MAX.
          const bool no_limit =
            m[3] == "MAX_DOUBLE" ||
            m[3] == std::to_string(std::numeric_limits<int>::max());
          return kind + (no_limit ?
                           " of at least " + m[2].str() :
                           " from " + m[2].str() + " to " + m[3].str());
        }
      return "[" + pattern + "]";
    }

    /// ParameterHandler's messages for a value that does not match its
    /// pattern, in words: "NAME = 'VALUE'; expected ...".
    std::string
    pattern_message_in_words(const std::string &text)
    {
      static const std::regex in_file(
        R"(The entry value (.*) for the entry named (.*) does not match the given pattern: \[(.*)\])");
      static const std::regex in_set(
        R"(The string <(.*)> does not match the given pattern <\[(.*)\]>\.?)");
      std::smatch m;
      if (std::regex_search(text, m, in_file))
        return m.prefix().str() + m[2].str() + " = '" + m[1].str() +
               "'; expected " + pattern_in_words(m[3].str()) + m.suffix().str();
      if (std::regex_search(text, m, in_set))
        return m.prefix().str() + "'" + m[1].str() + "'; expected " +
               pattern_in_words(m[2].str()) + m.suffix().str();
      return text;
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
    return pattern_message_in_words(
      std::regex_replace(result, prm_location, "line $1:"));
  }

  std::string
  number_text(const double value)
  {
    std::ostringstream text;
    text << value;
    return text.str();
  }
} // namespace RestShape
