// A log-log scatter plot as SVG (study mode's error against time).
#ifndef restshape_app_study_plot_h
#define restshape_app_study_plot_h

#include <string>
#include <vector>

namespace RestShape
{
  struct StudyPoint
  {
    double      x, y;
    std::string label;
  };

  /// Write @p points (those with x, y > 0) as a labelled log-log scatter
  /// plot to @p file (SVG, written atomically).
  void
  write_log_log_plot(const std::vector<StudyPoint> &points,
                     const std::string             &x_name,
                     const std::string             &y_name,
                     const std::string             &file);
} // namespace RestShape

#endif
