#include <deal.II/base/utilities.h>

#include <restshape/app/scene_input.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_names.h>

#include <filesystem>

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

  void
  read_scene(ParameterHandler               &prm,
             const std::string              &prm_file,
             const std::vector<std::string> &overrides)
  {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(prm_file, ec))
      throw InputError(prm_file, "", "no such scene file");
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
  }
} // namespace RestShape
