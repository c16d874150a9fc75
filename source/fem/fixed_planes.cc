#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/label_values.h>
#include <restshape/fem/fixed_planes.h>

#include <cmath>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// A face lies in a plane when its vertices are within this fraction
    /// of its size of it (round-off of a mesh file's coordinates).
    constexpr double plane_tolerance = 1e-6;

    FixedPlane
    parse_plane(const std::string &item, const std::string &parameter)
    {
      const auto        colon = item.find(':');
      const std::string plane = Utilities::trim(item.substr(0, colon));
      const auto        equal = plane.find('=');
      const std::string axis =
        Utilities::trim(plane.substr(0, std::min(equal, plane.size())));
      const std::string expected =
        "'" + item +
        "': expected 'AXIS = VALUE' or 'AXIS = VALUE: COMPONENTS', AXIS "
        "one of x, y, z, VALUE a coordinate in the mesh's length unit, "
        "e.g. 'x = 0' or 'y = 1: xz'";
      if (equal == std::string::npos || axis.size() != 1 || axis[0] < 'x' ||
          axis[0] > 'z')
        throw InputError("", parameter, expected);
      FixedPlane  result;
      const char *begin = plane.c_str() + equal + 1;
      char       *end   = nullptr;
      result.axis       = axis[0] - 'x';
      result.value      = std::strtod(begin, &end);
      if (end == begin || !Utilities::trim(end).empty() ||
          !std::isfinite(result.value))
        throw InputError("", parameter, expected);
      if (colon == std::string::npos)
        {
          result.components              = {{false, false, false}};
          result.components[result.axis] = true;
        }
      else
        result.components =
          parse_components(item,
                           Utilities::trim(item.substr(colon + 1)),
                           parameter,
                           "y = 1: xz");
      return result;
    }
  } // namespace

  bool
  FixedPlane::holds(const TriaAccessor<2, 3, 3> &face,
                    const double                 length_unit) const
  {
    const double position  = value * length_unit;
    const double tolerance = plane_tolerance * face.diameter();
    for (const unsigned int v : face.vertex_indices())
      if (std::abs(face.vertex(v)[axis] - position) > tolerance)
        return false;
    return true;
  }

  std::string
  FixedPlane::text() const
  {
    std::string comps;
    for (unsigned int c = 0; c < 3; ++c)
      if (components[c])
        comps += "xyz"[c];
    return std::string(1, "xyz"[axis]) + " = " + Utilities::to_string(value) +
           ": " + comps;
  }

  std::vector<FixedPlane>
  parse_fixed_planes(const std::string &text, const std::string &parameter)
  {
    std::vector<FixedPlane> result;
    for (const std::string &item : Utilities::split_string_list(text, ','))
      if (!Utilities::trim(item).empty())
        result.push_back(parse_plane(Utilities::trim(item), parameter));
    return result;
  }

  std::array<bool, 3>
  fixed_plane_components(const std::vector<FixedPlane> &planes,
                         const TriaAccessor<2, 3, 3>   &face,
                         const double                   length_unit)
  {
    std::array<bool, 3> result{{false, false, false}};
    for (const FixedPlane &plane : planes)
      if (plane.holds(face, length_unit))
        for (unsigned int c = 0; c < 3; ++c)
          result[c] = result[c] || plane.components[c];
    return result;
  }
} // namespace RestShape
