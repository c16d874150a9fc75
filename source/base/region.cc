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
      "(centre, axis direction and radius in the mesh's length unit) or "
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
    out << std::setprecision(4)
        << (shape == Shape::sphere ? "sphere at " : "cylinder through ")
        << vector_text(center, unit);
    if (shape == Shape::cylinder)
      out << " along " << vector_text(axis);
    out << " of radius " << radius / unit << ' ' << unit_name;
    return out.str();
  }

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
