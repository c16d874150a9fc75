#include <restshape/app/study_plot.h>
#include <restshape/base/atomic_file.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>

namespace RestShape
{
  namespace
  {
    constexpr double width = 640, height = 480, margin = 70;

    /// Decades [floor(log10 min), ceil(log10 max)] of the positive values.
    std::pair<double, double>
    decades(const std::vector<double> &values)
    {
      const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
      const double a      = std::floor(std::log10(*lo)),
                   b      = std::ceil(std::log10(*hi));
      return {a, b > a ? b : a + 1};
    }
  } // namespace

  void
  write_log_log_plot(const std::vector<StudyPoint> &all_points,
                     const std::string             &x_name,
                     const std::string             &y_name,
                     const std::string             &file)
  {
    std::vector<StudyPoint> points;
    for (const StudyPoint &p : all_points)
      if (p.x > 0 && p.y > 0 && std::isfinite(p.x) && std::isfinite(p.y))
        points.push_back(p);
    std::vector<double> xs, ys;
    for (const StudyPoint &p : points)
      {
        xs.push_back(p.x);
        ys.push_back(p.y);
      }
    const std::pair<double, double> x_range =
      xs.empty() ? std::make_pair(0., 1.) : decades(xs);
    const std::pair<double, double> y_range =
      ys.empty() ? std::make_pair(0., 1.) : decades(ys);
    const double x0 = x_range.first, x1 = x_range.second;
    const double y0 = y_range.first, y1 = y_range.second;
    const auto   sx = [&](const double x) {
      return margin + (std::log10(x) - x0) / (x1 - x0) * (width - 2 * margin);
    };
    const auto sy = [&](const double y) {
      return height - margin -
             (std::log10(y) - y0) / (y1 - y0) * (height - 2 * margin);
    };
    write_file_atomically(
      file,
      [&](std::ostream &out) {
        out << std::setprecision(5)
            << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width
            << "\" height=\"" << height
            << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
            << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
        for (double d = x0; d <= x1; ++d)
          out << "<line x1=\"" << sx(std::pow(10., d)) << "\" y1=\"" << margin
              << "\" x2=\"" << sx(std::pow(10., d)) << "\" y2=\""
              << height - margin << "\" stroke=\"#ddd\"/><text x=\""
              << sx(std::pow(10., d)) << "\" y=\"" << height - margin + 18
              << "\" text-anchor=\"middle\">1e" << d << "</text>\n";
        for (double d = y0; d <= y1; ++d)
          out << "<line x1=\"" << margin << "\" y1=\"" << sy(std::pow(10., d))
              << "\" x2=\"" << width - margin << "\" y2=\""
              << sy(std::pow(10., d)) << "\" stroke=\"#ddd\"/><text x=\""
              << margin - 6 << "\" y=\"" << sy(std::pow(10., d)) + 4
              << "\" text-anchor=\"end\">1e" << d << "</text>\n";
        out << "<text x=\"" << width / 2 << "\" y=\"" << height - 20
            << "\" text-anchor=\"middle\">" << x_name << "</text>\n"
            << "<text x=\"20\" y=\"" << height / 2
            << "\" text-anchor=\"middle\" transform=\"rotate(-90 20 "
            << height / 2 << ")\">" << y_name << "</text>\n";
        if (points.empty())
          out << "<text x=\"" << width / 2 << "\" y=\"" << height / 2
              << "\" text-anchor=\"middle\">no run has a positive " << y_name
              << " (see study.txt)</text>\n";
        for (const StudyPoint &p : points)
          out << "<circle cx=\"" << sx(p.x) << "\" cy=\"" << sy(p.y)
              << "\" r=\"4\" fill=\"#1f77b4\"/><text x=\"" << sx(p.x) + 6
              << "\" y=\"" << sy(p.y) - 6 << "\" font-size=\"10\">" << p.label
              << "</text>\n";
        out << "</svg>\n";
      },
      "Output/Directory");
  }
} // namespace RestShape
