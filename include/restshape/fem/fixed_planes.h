// Boundary conditions/Fixed boundary planes: displacement components held
// on the boundary faces that lie in a coordinate plane (a symmetry plane
// of a half or eighth model; a face held in its own plane).
#ifndef restshape_fem_fixed_planes_h
#define restshape_fem_fixed_planes_h

#include <deal.II/grid/tria_accessor.h>

#include <array>
#include <string>
#include <vector>

namespace RestShape
{
  struct FixedPlane
  {
    unsigned int        axis;  // 0, 1, 2: the plane x, y or z = value
    double              value; // in the mesh's length unit
    std::array<bool, 3> components;

    /// Whether every vertex of @p face lies in the plane (to a millionth
    /// of the face's size), its coordinates in metres and the plane's
    /// value in units of @p length_unit metres.
    bool
    holds(const dealii::TriaAccessor<2, 3, 3> &face,
          const double                         length_unit) const;
    /// 'y = 1: xz'.
    std::string
    text() const;
  };

  /// Parse 'x = 0, y = 1: xz, z = -2.5' (empty allowed): AXIS = VALUE in
  /// the mesh's length unit, then ': COMPONENTS' (a subset of xyz), by
  /// default the plane's normal component (a symmetry plane).
  std::vector<FixedPlane>
  parse_fixed_planes(const std::string &text, const std::string &parameter);

  /// The components that @p planes hold on @p face (none: all false).
  std::array<bool, 3>
  fixed_plane_components(const std::vector<FixedPlane>       &planes,
                         const dealii::TriaAccessor<2, 3, 3> &face,
                         const double                         length_unit);
} // namespace RestShape

#endif
