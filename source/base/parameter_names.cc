#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/parameter_names.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// Lower case, without blanks and apostrophes: "Youngs modulus" and
    /// "Young's Modulus" are the same name.
    std::string
    normalized(const std::string &name)
    {
      std::string n;
      for (const char c : name)
        if (c != ' ' && c != '\'' && c != '_')
          n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return n;
    }

    /// Levenshtein distance.
    unsigned int
    distance(const std::string &a, const std::string &b)
    {
      std::vector<unsigned int> row(b.size() + 1);
      for (unsigned int j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (unsigned int i = 1; i <= a.size(); ++i)
        {
          unsigned int diagonal = row[0];
          row[0]                = i;
          for (unsigned int j = 1; j <= b.size(); ++j)
            {
              const unsigned int up = row[j];
              row[j]                = std::min({row[j] + 1,
                                                row[j - 1] + 1,
                                                diagonal + (a[i - 1] != b[j - 1])});
              diagonal              = up;
            }
        }
      return row[b.size()];
    }

    std::string
    last_part(const std::string &path)
    {
      const auto slash = path.rfind('/');
      return slash == std::string::npos ? path : path.substr(slash + 1);
    }

    std::string
    join(const std::vector<std::string> &parts, const std::string &last)
    {
      std::string path;
      for (const std::string &p : parts)
        path += p + "/";
      return path + last;
    }

    /// "A/B/C" of the subsections {A, B, C}.
    std::string
    path_of(const std::vector<std::string> &stack)
    {
      std::string path;
      for (const std::string &s : stack)
        path += (path.empty() ? "" : "/") + s;
      return path;
    }

    /// "set Name = value" -> "Name"; "subsection Name" -> "Name".
    std::string
    after_keyword(const std::string &line, const std::string &keyword)
    {
      std::string rest = line.substr(keyword.size());
      if (keyword == "set")
        rest = rest.substr(0, rest.find('='));
      return dealii::Utilities::trim(rest);
    }

    bool
    starts_with_word(const std::string &line, const std::string &word)
    {
      return line.rfind(word, 0) == 0 &&
             (line.size() == word.size() || line[word.size()] == ' ' ||
              line[word.size()] == '\t');
    }
  } // namespace

  ParameterNames::ParameterNames(const dealii::ParameterHandler &prm)
  {
    std::ostringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    std::istringstream       in(text.str());
    std::vector<std::string> stack;
    for (std::string line; std::getline(in, line);)
      {
        line = dealii::Utilities::trim(line);
        if (starts_with_word(line, "subsection"))
          {
            stack.push_back(after_keyword(line, "subsection"));
            subsections.insert(path_of(stack));
          }
        else if (line == "end" && !stack.empty())
          stack.pop_back();
        else if (starts_with_word(line, "set"))
          entries.insert(join(stack, after_keyword(line, "set")));
      }
  }

  std::vector<std::string>
  nearest_names(const std::string &path, const std::set<std::string> &known)
  {
    const std::string name = normalized(last_part(path));
    // The nearest names anywhere (the name may be in another subsection),
    // at most three, within a third of the name's length.
    std::vector<std::pair<unsigned int, std::string>> near;
    for (const std::string &k : known)
      {
        const std::string other = normalized(last_part(k));
        // A name cut short ("Grav") is near its full form.
        const unsigned int d = other.rfind(name, 0) == 0 && !name.empty() ?
                                 1 :
                                 distance(name, other);
        near.emplace_back(d, k);
      }
    std::sort(near.begin(), near.end());
    const unsigned int       limit = std::max<unsigned int>(2, name.size() / 3);
    std::vector<std::string> result;
    for (unsigned int i = 0; i < near.size() && i < 3; ++i)
      if (near[i].first <= limit)
        result.push_back(near[i].second);
    return result;
  }

  std::string
  did_you_mean(const std::vector<std::string> &names)
  {
    std::string list;
    for (const std::string &n : names)
      list += (list.empty() ? "" : ", ") + ("'" + n + "'");
    return list.empty() ? "" : "; did you mean " + list + "?";
  }

  std::string
  ParameterNames::unknown_text(const std::string           &kind,
                               const std::string           &path,
                               const std::set<std::string> &known) const
  {
    const std::string text = "unknown " + kind + " '" + path + "'";
    // Names that an earlier version had, and what replaced them.
    static const std::map<std::string, std::string> renamed = {
      {"Prestress comparison",
       "replaced by 'Scenario' (doc/scenarios.md; 'Extra body force' is "
       "now 'Tissue body force', not buoyed)"}};
    for (const auto &[old_name, replacement] : renamed)
      if (path == old_name || path.rfind(old_name + "/", 0) == 0)
        return text + ": " + replacement;
    const std::string near = did_you_mean(nearest_names(path, known));
    return text + (near.empty() ? "; see restshape --print-parameters" : near);
  }

  void
  ParameterNames::check_entry(const std::string &path) const
  {
    const auto slash = path.rfind('/');
    if (slash != std::string::npos && !subsections.count(path.substr(0, slash)))
      throw InputError("--set",
                       path,
                       unknown_text("subsection",
                                    path.substr(0, slash),
                                    subsections));
    if (!entries.count(path))
      throw InputError("--set", path, unknown_text("parameter", path, entries));
  }

  void
  ParameterNames::check_top_subsection(const std::string &path) const
  {
    if (path.find('/') != std::string::npos || !subsections.count(path))
      throw InputError("--print-parameters",
                       "",
                       unknown_text("subsection", path, subsections));
  }

  void
  ParameterNames::check_file(const std::string &file) const
  {
    std::ifstream            in(file);
    std::vector<std::string> stack;
    unsigned int             number = 0;
    for (std::string line; std::getline(in, line);)
      {
        ++number;
        line = dealii::Utilities::trim(line.substr(0, line.find('#')));
        const std::string where = "line " + std::to_string(number);
        if (starts_with_word(line, "include"))
          check_file(after_keyword(line, "include"));
        else if (starts_with_word(line, "subsection"))
          {
            stack.push_back(after_keyword(line, "subsection"));
            const std::string path = path_of(stack);
            if (!subsections.count(path))
              throw InputError(file,
                               where,
                               unknown_text("subsection", path, subsections));
          }
        else if (line == "end" && !stack.empty())
          stack.pop_back();
        else if (starts_with_word(line, "set"))
          {
            const std::string path = join(stack, after_keyword(line, "set"));
            if (!entries.count(path))
              throw InputError(file,
                               where,
                               unknown_text("parameter", path, entries));
          }
      }
  }
} // namespace RestShape
