// HeldPlanes: the crease logic of an active contact node. A node that
// leaves a face and comes back to it holds both faces' planes (a crease);
// faces within the crease angle make one fixed plane with their mean
// normal; a third independent face makes a corner; a node off its planes
// follows the closest face again; too many changes fix the planes; planes
// are dropped by bit mask; the constrained gap is the farthest from 0.
#include <restshape/contact/held_planes.h>

#include <cmath>
#include <string>

#include "checks.h"

using namespace RestShape;
using namespace checks;
using dealii::Point;
using dealii::Tensor;

namespace
{
  Tensor<1, 3>
  unit(const double x, const double y, const double z)
  {
    Tensor<1, 3> t;
    t[0] = x;
    t[1] = y;
    t[2] = z;
    return t / t.norm();
  }

  /// The gap of @p x to the plane z = 0 tilted about the y axis by
  /// @p degrees (normal towards +z).
  Gap
  face(const Point<3> &x, const double degrees)
  {
    const double       a = degrees * M_PI / 180;
    const Tensor<1, 3> n = unit(std::sin(a), 0, std::cos(a));
    return Gap{n * x, n, n};
  }

  /// The node at @p x meets the faces tilted by @p tilts in turn (the
  /// closest face remembered after each update, as ContactProblem does).
  HeldPlanes
  walk(const Point<3>            &x,
       const std::vector<double> &tilts,
       Tensor<1, 3>              &normal,
       const unsigned int         max_changes = 3)
  {
    HeldPlanes planes;
    for (const double t : tilts)
      {
        planes.update(x, face(x, t), 1e-9, max_changes, normal);
        planes.set_closest_face(x, face(x, t));
      }
    return planes;
  }

  bool
  near(const double a, const double b)
  {
    return std::abs(a - b) <= 1e-12;
  }
} // namespace

int
main()
{
  const Point<3> x(0, 0, 0);
  Tensor<1, 3>   normal;

  HeldPlanes one = walk(x, {0, 0}, normal);
  expect(one.planes().empty() && normal == unit(0, 0, 1),
         "a node on one face holds no plane and takes the face's normal");

  HeldPlanes left = walk(x, {0, 30}, normal);
  expect(left.planes().empty() && normal == face(x, 30).gradient,
         "a node that moves on to another face follows it");

  HeldPlanes crease = walk(x, {0, 30, 0}, normal);
  expect(crease.planes().size() == 2 && !crease.fixed(),
         "back on a face it left: the planes of both faces (a crease)");
  expect((normal - unit(std::sin(M_PI / 12), 0, std::cos(M_PI / 12))).norm() <
           1e-12,
         "the crease normal is the mean of the two faces' normals");

  HeldPlanes flat = walk(x, {0, 5, 0}, normal);
  expect(flat.planes().size() == 1 && flat.fixed(),
         "faces within " +
           std::to_string(int(HeldPlanes::crease_angle_degrees)) +
           " degrees: one fixed plane");
  expect((flat.planes()[0].normal -
          unit(std::sin(M_PI / 72), 0, std::cos(M_PI / 72)))
             .norm() < 1e-12,
         "with the mean normal of the two faces");

  // Through a third face, independent of the crease: a corner.
  HeldPlanes         corner = walk(x, {0, 30, 0}, normal);
  const double       b      = 40 * M_PI / 180;
  const Tensor<1, 3> n3     = unit(0, std::sin(b), std::cos(b));
  const Point<3>     below(0, 0, -1e-3);
  corner.update(below, Gap{n3 * below, n3, n3}, 1e-9, 3, normal);
  expect(corner.planes().size() == 3, "through a third face: a corner");

  // Off the surface (positive gap, no held face's normal): let go.
  HeldPlanes     off = walk(x, {0, 30, 0}, normal);
  const Point<3> above(0, 0, 1e-3);
  off.update(above, Gap{n3 * above, n3, n3}, 1e-9, 3, normal);
  expect(off.planes().empty() && normal == n3,
         "off the surface: the node follows the closest face again");

  // Held, let go, held again ... : after max_changes changes, fixed.
  HeldPlanes busy = walk(x, {0, 30, 0}, normal, 0);
  expect(busy.fixed() && busy.planes().size() == 2,
         "more changes than allowed: the planes are fixed");
  const Tensor<1, 3> before = normal;
  busy.update(above, face(above, 60), 1e-9, 0, normal);
  expect(normal == before && busy.planes().size() == 2,
         "fixed planes keep the node's normal and planes");
  expect(near(busy.mean_plane().gap,
              busy.mean_plane().normal * (above - busy.mean_plane().point)),
         "fixed planes: the mean plane's gap follows the node");
  const double g0 = busy.planes()[0].gap, g1 = busy.planes()[1].gap;
  expect(near(busy.constrained_gap(false),
              std::abs(g0) > std::abs(g1) ? g0 : g1) &&
           near(busy.constrained_gap(true), busy.mean_plane().gap),
         "the constrained gap: the held plane farthest from 0, or the mean");

  HeldPlanes dropped = walk(x, {0, 30, 0}, normal);
  expect(dropped.drop(1u) && dropped.planes().size() == 1 &&
           dropped.normal() == face(x, 30).gradient,
         "dropping plane 0 by its bit leaves the other");
  expect(!dropped.drop(0u) && dropped.planes().size() == 1,
         "an empty mask drops nothing");
  dropped.reset();
  expect(dropped.planes().empty() && !dropped.fixed(),
         "reset forgets everything");
  return failures == 0 ? 0 : 1;
}
