// A region of space given in a scene file.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/region.h>
#include <restshape/base/vector_text.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    const std::string region_format =
      "expected 'sphere: x, y, z, r', 'cylinder: x, y, z, ax, ay, az, r' "
      "(centre, axis direction and radius in the mesh's length unit), "
      "'box: x0, y0, z0, x1, y1, z1' (two opposite corners) or "
      "'surface: FILE' (a closed surface, .off, .stl or .obj, in the mesh's "
      "length unit)";
  } // namespace

  bool
  Region::contains(const Point<3> &x) const
  {
    const Tensor<1, 3> r = x - center;
    switch (shape)
      {
        case Shape::sphere:
          return r.norm() <= radius;
        case Shape::cylinder:
          return (r - (r * axis) * axis).norm() <= radius;
        case Shape::box:
          for (unsigned int d = 0; d < 3; ++d)
            if (x[d] < center[d] || x[d] > upper[d])
              return false;
          return true;
        case Shape::surface:
          AssertThrow(inside,
                      ExcMessage("the surface " + file + " was not read"));
          return (*inside)(x);
        case Shape::none:
          break;
      }
    return false;
  }

  void
  Region::scale(const double factor)
  {
    center *= factor;
    upper *= factor;
    radius *= factor;
    unit *= factor;
  }

  std::string
  Region::text(const double unit, const std::string &unit_name) const
  {
    if (shape == Shape::none)
      return "none";
    if (shape == Shape::surface)
      return "inside of the surface " + file;
    std::ostringstream out;
    out << std::setprecision(4);
    if (shape == Shape::box)
      {
        out << "box from " << vector_text(center, unit) << " to "
            << vector_text(upper, unit) << ' ' << unit_name;
        return out.str();
      }
    out << (shape == Shape::sphere ? "sphere at " : "cylinder through ")
        << vector_text(center, unit);
    if (shape == Shape::cylinder)
      out << " along " << vector_text(axis);
    out << " of radius " << radius / unit << ' ' << unit_name;
    return out.str();
  }

  namespace
  {
    /// A box from two opposite corners, in any order.
    Region
    parse_box(const std::vector<double> &v, const std::string &parameter)
    {
      Region region;
      region.shape = Region::Shape::box;
      for (unsigned int d = 0; d < 3; ++d)
        {
          region.center[d] = std::min(v[d], v[d + 3]);
          region.upper[d]  = std::max(v[d], v[d + 3]);
          if (!(region.upper[d] > region.center[d]))
            throw InputError("",
                             parameter,
                             std::string("the box has no extent in ") +
                               "xyz"[d] + "; " + region_format);
        }
      return region;
    }
  } // namespace

  Region
  parse_region(const std::string &text, const std::string &parameter)
  {
    Region            region;
    const std::string trimmed = Utilities::trim(text);
    if (trimmed.empty())
      return region;
    const auto colon = trimmed.find(':');
    if (colon == std::string::npos)
      throw InputError("", parameter, "'" + trimmed + "': " + region_format);
    const std::string shape = Utilities::trim(trimmed.substr(0, colon));
    if (shape == "surface")
      {
        region.shape = Region::Shape::surface;
        region.file  = Utilities::trim(trimmed.substr(colon + 1));
        if (region.file.empty())
          throw InputError("", parameter, "no file given; " + region_format);
        return region;
      }
    const std::vector<std::string> fields =
      Utilities::split_string_list(trimmed.substr(colon + 1), ',');
    std::vector<double> v;
    for (const std::string &f : fields)
      v.push_back(parse_number(parameter, f));
    if (shape == "sphere" && v.size() == 4)
      {
        region.shape  = Region::Shape::sphere;
        region.center = Point<3>(v[0], v[1], v[2]);
        region.radius = v[3];
      }
    else if (shape == "cylinder" && v.size() == 7)
      {
        region.shape  = Region::Shape::cylinder;
        region.center = Point<3>(v[0], v[1], v[2]);
        region.axis   = Tensor<1, 3>({v[3], v[4], v[5]});
        region.radius = v[6];
        if (!(region.axis.norm() > 0))
          throw InputError("",
                           parameter,
                           "the cylinder's axis direction is zero; " +
                             region_format);
        region.axis /= region.axis.norm();
      }
    else if (shape == "box" && v.size() == 6)
      return parse_box(v, parameter);
    else
      throw InputError("", parameter, "'" + trimmed + "': " + region_format);
    if (!(region.radius > 0))
      throw InputError("",
                       parameter,
                       "radius " + number_text(region.radius) +
                         "; expected a radius > 0, " + region_format);
    return region;
  }
} // namespace RestShape
