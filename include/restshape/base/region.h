// A region of space given in a scene file: a ball or an unbounded cylinder.
#ifndef restshape_base_region_h
#define restshape_base_region_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>

namespace RestShape
{
  /**
   * A ball (centre, radius) or an unbounded circular cylinder (a point of
   * its axis, the axis direction, radius), in the unit it was given in
   * until scale() converts it (to metres).
   */
  struct Region
  {
    enum class Shape
    {
      none,
      sphere,
      cylinder
    };
    Shape                shape = Shape::none;
    dealii::Point<3>     center;
    dealii::Tensor<1, 3> axis; // unit vector (cylinder)
    double               radius = 0;

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
   * 'sphere: x, y, z, r' or 'cylinder: x, y, z, ax, ay, az, r' (lengths in
   * the unit of the text); an empty text gives no region. Throws InputError
   * naming @p parameter with the expected format.
   */
  Region
  parse_region(const std::string &text, const std::string &parameter);
} // namespace RestShape

#endif
