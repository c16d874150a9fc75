#include <deal.II/base/utilities.h>

#include <restshape/app/parameters.h>
#include <restshape/app/scene_input.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_names.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace RestShape
{
  using namespace dealii;

  void
  apply_override(ParameterHandler  &prm,
                 const std::string &assignment,
                 const std::string &option)
  {
    const auto equal = assignment.find('=');
    if (equal == std::string::npos)
      throw InputError(option,
                       assignment,
                       "expected 'Subsection/Parameter=value'");
    const std::string path  = Utilities::trim(assignment.substr(0, equal));
    const std::string value = Utilities::trim(assignment.substr(equal + 1));
    const auto        parts = Utilities::split_string_list(path, '/');
    if (parts.size() < 2)
      throw InputError(option, path, "expected 'Subsection/Parameter=value'");
    try
      {
        ParameterNames(prm).check_entry(path);
      }
    catch (const InputError &e)
      {
        throw InputError(option, e.parameter, e.message);
      }
    for (unsigned int i = 0; i + 1 < parts.size(); ++i)
      prm.enter_subsection(parts[i]);
    try
      {
        prm.set(parts.back(), value);
      }
    catch (const std::exception &exc)
      {
        for (unsigned int i = 0; i + 1 < parts.size(); ++i)
          prm.leave_subsection();
        throw InputError(option, path, one_line_message(exc));
      }
    for (unsigned int i = 0; i + 1 < parts.size(); ++i)
      prm.leave_subsection();
  }

  namespace
  {
    /// Includes nested deeper than this are refused.
    constexpr unsigned int max_include_depth = 16;

    /**
     * The include lines of @p file and of the files they include, checked
     * before deal.II reads them: every included file exists and is a
     * regular file, none includes itself again (deal.II's reader recursed
     * until the stack overflowed), nesting stays below max_include_depth.
     * @p chain: the files being read, outermost first.
     */
    /// The subsection that holds the first scenario; further ones are
    /// "Scenario NAME".
    const std::string scenario_section = "Scenario";

    /// Add NAME of a subsection "Scenario NAME" (@p section) to @p names
    /// once; InputError naming @p where for a NAME that cannot name files.
    void
    add_scenario_name(const std::string        &section,
                      const std::string        &where,
                      std::vector<std::string> &names)
    {
      const std::string prefix = scenario_section + " ";
      if (section.rfind(prefix, 0) != 0)
        return;
      const std::string name = Utilities::trim(section.substr(prefix.size()));
      for (const char c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' &&
            c != '-')
          throw InputError(where,
                           section,
                           "a scenario's name names its output files: "
                           "expected letters, digits, '-' and '_'");
      if (!name.empty() &&
          std::find(names.begin(), names.end(), name) == names.end())
        names.push_back(name);
    }

    void
    check_includes(const std::string        &file,
                   std::vector<std::string> &chain,
                   std::vector<std::string> &scenarios)
    {
      namespace fs = std::filesystem;
      std::ifstream in(file);
      std::string   line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          line = Utilities::trim(line);
          if (line.rfind("subsection ", 0) == 0)
            add_scenario_name(Utilities::trim(line.substr(11)),
                              file + ":" + std::to_string(number),
                              scenarios);
          if (line.rfind("include", 0) != 0 || line.size() < 8 ||
              !std::isspace(static_cast<unsigned char>(line[7])))
            continue;
          const std::string name = Utilities::trim(line.substr(8));
          const auto        fail = [&](const std::string &what) {
            throw InputError(file,
                             "",
                             "line " + std::to_string(number) + ": include " +
                               name + ": " + what);
          };
          std::error_code ec;
          if (fs::is_directory(name, ec))
            fail("a directory; expected a parameter file");
          if (!fs::is_regular_file(name, ec))
            fail("no such file (paths are relative to the working "
                 "directory)");
          for (const std::string &outer : chain)
            if (fs::equivalent(outer, name, ec))
              fail("includes " + outer + " again (an include cycle)");
          if (chain.size() >= max_include_depth)
            fail("includes nested more than " +
                 std::to_string(max_include_depth) + " deep");
          chain.push_back(name);
          check_includes(name, chain, scenarios);
          chain.pop_back();
        }
    }
  } // namespace

  std::vector<std::string>
  read_scene(ParameterHandler               &prm,
             const std::string              &prm_file,
             const std::vector<std::string> &overrides)
  {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(prm_file, ec))
      throw InputError(prm_file, "", "no such scene file");
    std::vector<std::string> chain = {prm_file}, scenarios;
    check_includes(prm_file, chain, scenarios);
    for (const std::string &o : overrides)
      add_scenario_name(Utilities::trim(
                          o.substr(0, std::min(o.find('/'), o.find('=')))),
                        "--set",
                        scenarios);
    for (const std::string &name : scenarios)
      ScenarioParameters::declare_parameters(prm, name);
    try
      {
        prm.parse_input(prm_file, "", false, true);
      }
    catch (const std::exception &exc)
      {
        // Misspelled names: the file, line and the nearest known names.
        ParameterNames(prm).check_file(prm_file);
        throw InputError(prm_file, "", one_line_message(exc));
      }
    for (const std::string &o : overrides)
      apply_override(prm, o);
    return scenarios;
  }
} // namespace RestShape
