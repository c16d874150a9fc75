// Study mode: one scene over every combination of parameter values, each
// run in its own output folder, summarised in one table and one plot.
#ifndef restshape_app_study_h
#define restshape_app_study_h

#include <string>
#include <vector>

namespace RestShape
{
  /// "Discretization/Polynomial degree=1,2": a parameter and its values.
  struct StudyAxis
  {
    std::string              parameter;
    std::vector<std::string> values;

    /// Throws InputError ("--study") unless @p text is "Sub/Param=v1,v2...".
    static StudyAxis
    parse(const std::string &text);
  };

  /**
   * Run @p prm_file (with @p overrides) once per combination of the values
   * of @p axes, each as a separate process of @p program (so that each
   * run's time and peak memory are its own) writing to
   * OUTPUT/study/NN_.../, where OUTPUT is the scene's Output/Directory.
   * Then write OUTPUT/study/study.csv and study.txt (one row per run:
   * the values, DoFs, Newton and inverse iterations, the errors the runs
   * measure - exact ones where Verification gives them, else the relative
   * difference of the largest displacement from the run with the most
   * DoFs -, wall seconds and peak memory) and study_error_vs_time.svg.
   * Prints one line per run. Returns the exit code: 0 if every run
   * succeeded, else the largest of the runs' codes.
   */
  int
  run_study(const std::string              &program,
            const std::string              &prm_file,
            const std::vector<std::string> &overrides,
            const std::vector<StudyAxis>   &axes);
} // namespace RestShape

#endif
