// A rigid obstacle: a closed, outward-oriented triangulated surface (CGAL),
// with closest-point and inside/outside queries through an AABB tree.
#ifndef restshape_obstacle_h
#define restshape_obstacle_h

#include <deal.II/base/point.h>

#include <memory>
#include <string>

namespace RestShape
{
  /// The signed distance of a point to the obstacle, on the allowed side.
  struct Gap
  {
    double gap; // > 0 on the allowed side, < 0 beyond (m)
    dealii::Tensor<1, 3>
      normal; // smoothed (Phong) normal, towards the allowed side
    dealii::Tensor<1, 3>
      gradient; // exact gradient of the gap (closest face's normal
                // on the surface), towards the allowed side
  };

  class Obstacle
  {
  public:
    /**
     * Read @p file (.stl, .off, .obj; coordinates in @p length_unit metres)
     * and check it: a closed, 2-manifold, outward-oriented triangle surface
     * without self-intersections. @p inside: the allowed side is the bounded
     * region (a skull); otherwise the unbounded one (an obstacle). Throws
     * InputError naming the file and Contact/Obstacle file.
     */
    Obstacle(const std::string &file,
             const double       length_unit,
             const bool         inside);
    ~Obstacle();

    Gap
    gap(const dealii::Point<3> &x) const;

    /// Whether the segment from @p a to @p b crosses the surface.
    unsigned int
    n_crossings(const dealii::Point<3> &a, const dealii::Point<3> &b) const;

    unsigned int
    n_triangles() const;

    /// The surface's vertices (m).
    std::vector<dealii::Point<3>>
    vertices() const;

    /// The corners (m) of the obstacle's bounding box.
    std::pair<dealii::Point<3>, dealii::Point<3>>
    bounding_box() const;

  private:
    struct Data;
    std::unique_ptr<Data> data;
    const bool            inside;
  };
} // namespace RestShape

#endif
