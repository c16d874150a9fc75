// Reading a scene: its .prm file and the --set overrides of the command
// line, with errors that name the file, the line and the nearest names.
#ifndef restshape_app_scene_input_h
#define restshape_app_scene_input_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace RestShape
{
  /// Apply "Sub/Sub/Parameter=value" to @p prm; InputError naming
  /// @p option for an unknown name (with the nearest ones) or a value its
  /// pattern refuses.
  void
  apply_override(dealii::ParameterHandler &prm,
                 const std::string        &assignment,
                 const std::string        &option = "--set");

  /**
   * Read @p prm_file into @p prm (declared), then apply @p overrides.
   * Subsections "Scenario NAME" of the file, its includes and the
   * overrides are declared first; returns their NAMEs in the order
   * written (for Parameters::parse_parameters()). Throws InputError naming
   * the file (and line, for unknown names).
   */
  std::vector<std::string>
  read_scene(dealii::ParameterHandler       &prm,
             const std::string              &prm_file,
             const std::vector<std::string> &overrides);
} // namespace RestShape

#endif
