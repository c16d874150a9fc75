// HeldPlanes: the planes an active contact node holds in a crease or
// corner of the triangulated obstacle (see held_planes.h).
#include <restshape/contact/held_planes.h>

#include <algorithm>
#include <cmath>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    double
    crease_sine()
    {
      return std::sin(HeldPlanes::crease_angle_degrees * M_PI / 180);
    }
  } // namespace

  bool
  HeldPlanes::same(const Tensor<1, 3> &a, const Tensor<1, 3> &b)
  {
    return (a - b).norm() <= same_normal_tolerance;
  }

  bool
  HeldPlanes::holds(const Tensor<1, 3> &normal) const
  {
    return std::any_of(held.begin(), held.end(), [&](const ContactPlane &p) {
      return same(p.normal, normal);
    });
  }

  void
  HeldPlanes::update(const Point<3>    &x,
                     const Gap         &g,
                     const double       gap_tolerance,
                     const unsigned int max_changes,
                     Tensor<1, 3>      &normal)
  {
    // (Re-planing a node on fixed planes that slid more than h_min / 1000
    // or h_min / 10 off the surface was tried: more Newton steps on the P1
    // brain at gravity x 10.)
    if (fixed_planes)
      {
        update_gaps(x);
        return;
      }
    const ContactPlane current{g.gradient, x - g.gap * g.gradient, g.gap};
    if (held.empty())
      follow_faces(current, g);
    else if (std::abs(g.gap) > gap_tolerance && !holds(g.gradient))
      meet_face(current, g);
    // A node whose planes keep changing (held, let go, held again; or two
    // faces replacing each other: 2-cycles seen with P2 at gravity x 10)
    // keeps its planes (or the closest face's) for the rest of the solve.
    // (A mean normal with the distance to the surface as gap, used before,
    // converged linearly.)
    if (changes > max_changes)
      {
        if (held.empty())
          held = {current};
        fixed_planes = true;
      }
    update_gaps(x);
    normal = held.empty() ? g.gradient : this->normal();
  }

  void
  HeldPlanes::follow_faces(const ContactPlane &current, const Gap &g)
  {
    if (face.normal.norm() == 0 || same(g.gradient, face.normal))
      return;
    const bool back =
      std::any_of(left.begin(), left.end(), [&](const ContactPlane &p) {
        return same(p.normal, g.gradient);
      });
    if (back &&
        cross_product_3d(g.gradient, face.normal).norm() < crease_sine())
      {
        // Faces within the crease angle: one plane with the mean of their
        // normals through the closest point, fixed for the rest of the
        // solve. (The mean normal with the distance to the surface as gap,
        // used before, converged linearly, by about 0.6 per step.)
        const Tensor<1, 3> sum = g.gradient + face.normal;
        held         = {ContactPlane{sum / sum.norm(), current.point}};
        fixed_planes = true;
      }
    else if (back)
      {
        held = {current, face};
        ++changes;
      }
    else
      {
        left.push_back(face);
        if (left.size() > faces_remembered)
          left.erase(left.begin());
      }
  }

  void
  HeldPlanes::meet_face(const ContactPlane &current, const Gap &g)
  {
    ++changes;
    if (g.gap > 0)
      {
        // Off the surface, held by planes whose faces it has slid past
        // (over a ridge): it follows the closest face again.
        held.clear();
        return;
      }
    // Through another face: held too, if independent of the held planes;
    // otherwise it replaces the held plane closest to it.
    auto closest = held.begin();
    for (auto p = held.begin(); p != held.end(); ++p)
      if (p->normal * g.gradient > closest->normal * g.gradient)
        closest = p;
    const double s = crease_sine();
    const bool   independent =
      held.size() == 1 ?
          cross_product_3d(closest->normal, g.gradient).norm() > s :
        held.size() == 2 ?
          std::abs(cross_product_3d(held[0].normal, held[1].normal) *
                 g.gradient) > s * s :
          false;
    if (independent)
      held.push_back(current);
    else
      *closest = current;
  }

  void
  HeldPlanes::update_gaps(const Point<3> &x)
  {
    for (ContactPlane &p : held)
      p.gap = p.normal * (x - p.point);
    if (!fixed_planes || held.empty())
      return;
    mean = ContactPlane();
    for (const ContactPlane &p : held)
      {
        mean.normal += p.normal;
        mean.point += p.point / double(held.size());
      }
    mean.normal /= mean.normal.norm();
    mean.gap = mean.normal * (x - mean.point);
  }

  void
  HeldPlanes::set_closest_face(const Point<3> &x, const Gap &g)
  {
    face = ContactPlane{g.gradient, x - g.gap * g.gradient, g.gap};
  }

  void
  HeldPlanes::let_go()
  {
    fixed_planes = false;
    changes      = 0;
    left.clear();
    held.clear();
  }

  void
  HeldPlanes::reset()
  {
    face = ContactPlane();
    let_go();
  }

  bool
  HeldPlanes::drop(const unsigned int mask)
  {
    for (int i = int(held.size()) - 1; i >= 0; --i)
      if (mask & (1u << i))
        held.erase(held.begin() + i);
    return mask != 0 && !held.empty();
  }

  Tensor<1, 3>
  HeldPlanes::normal() const
  {
    Tensor<1, 3> sum;
    for (const ContactPlane &p : held)
      sum += p.normal;
    return sum / sum.norm();
  }

  double
  HeldPlanes::constrained_gap(const bool mean_imposed) const
  {
    if (mean_imposed)
      return mean.gap;
    double gap = 0;
    for (const ContactPlane &p : held)
      if (std::abs(p.gap) > std::abs(gap))
        gap = p.gap;
    return gap;
  }
} // namespace RestShape
