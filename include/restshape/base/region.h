// A region of space given in a scene file: a ball, an unbounded cylinder,
// a box or the inside of a closed surface file.
#ifndef restshape_base_region_h
#define restshape_base_region_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <memory>
#include <string>

namespace RestShape
{
  /**
   * A ball (centre, radius), an unbounded circular cylinder (a point of
   * its axis, the axis direction, radius), a box aligned with the axes
   * (two opposite corners) or the inside of a closed
   * surface file, in the unit it was given in until scale() converts it
   * (to metres). A surface's inside test is set by whoever reads the file
   * (ScenarioParameters::read_surfaces(): the contact part does).
   */
  struct Region
  {
    enum class Shape
    {
      none,
      sphere,
      cylinder,
      box,
      surface
    };
    using InsideTest = std::function<bool(const dealii::Point<3> &)>;

    Shape                             shape = Shape::none;
    dealii::Point<3>                  center; // box: its lower corner
    dealii::Point<3>                  upper;  // box: its upper corner
    dealii::Tensor<1, 3>              axis;   // unit vector (cylinder)
    double                            radius = 0;
    std::string                       file;     // surface
    double                            unit = 1; // surface: metres per file unit
    std::shared_ptr<const InsideTest> inside;   // surface, once read

    bool
    defined() const
    {
      return shape != Shape::none;
    }
    /// Whether @p x lies inside (or on the boundary).
    bool
    contains(const dealii::Point<3> &x) const;
    /// Lengths times @p factor.
    void
    scale(const double factor);
    /// "sphere at (x, y, z) of radius r" in @p unit_name, lengths divided
    /// by @p unit (the unit's length in the current one).
    std::string
    text(const double unit, const std::string &unit_name) const;
  };

  /**
   * 'sphere: x, y, z, r', 'cylinder: x, y, z, ax, ay, az, r', 'box: x0, y0,
   * z0, x1, y1, z1' (lengths in
   * the unit of the text) or 'surface: FILE'; an empty text gives no
   * region. Throws InputError
   * naming @p parameter with the expected format.
   */
  Region
  parse_region(const std::string &text, const std::string &parameter);
} // namespace RestShape

#endif
