// ContactProblem: the planes an active node holds in a crease or corner of
// the triangulated obstacle while releases are frozen (see
// update_active_set() in contact.cc).
#include <restshape/contact/contact.h>

#include <cmath>

namespace RestShape
{
  using namespace dealii;

  void
  ContactProblem::update_held_planes(Candidate      &c,
                                     const Point<3> &x,
                                     const Gap      &g)
  {
    // An active node takes the exact gradient of the gap as its normal, so
    // Newton converges quadratically while it stays on one face. A node
    // that comes back to a face it has left rests in a crease of the
    // triangulated surface, where the closest face alternates (2- and
    // 3-cycles; at heavy load most contact nodes of the brain). It then
    // holds the planes of both faces at once, so it slides along the
    // crease, and its constraints are linear: quadratic convergence again.
    // (A smoothed normal fixed for the rest of the solve, used before,
    // converged linearly, by 0.8 per step.) A held node that goes through a
    // third face holds that one too (a corner). Held planes that pull on
    // the node (negative multiplier) are let go by thaw_if_adhesive(), like
    // pulling nodes: letting them go at once made the planes of a node come
    // and go in a 2-cycle.
    const auto same = [](const Tensor<1, 3> &a, const Tensor<1, 3> &b) {
      return (a - b).norm() <= 1e-6;
    };
    const double crease_sine = std::sin(10 * M_PI / 180);
    const Plane  current{g.gradient, x - g.gap * g.gradient, g.gap};
    const auto   update_gaps = [&]() {
      for (Plane &p : c.held)
        p.gap = p.normal * (x - p.point);
      if (c.fixed_planes && !c.held.empty())
        {
          Plane &mean = c.mean_plane;
          mean        = Plane();
          for (const Plane &p : c.held)
            {
              mean.normal += p.normal;
              mean.point += p.point / double(c.held.size());
            }
          mean.normal /= mean.normal.norm();
          mean.gap = mean.normal * (x - mean.point);
        }
    };
    if (c.fixed_planes)
      {
        // (Re-planing a node that slid more than h_min / 1000 or h_min / 10
        // off the surface was tried: more Newton steps on the P1 brain at
        // gravity x 10, doc/benchmarks.md.)
        update_gaps();
        return;
      }
    if (c.held.empty())
      {
        if (c.face.normal.norm() > 0 && !same(g.gradient, c.face.normal))
          {
            const bool back =
              std::any_of(c.left.begin(), c.left.end(), [&](const Plane &p) {
                return same(p.normal, g.gradient);
              });
            // Faces within 10 degrees of each other (two planes would be
            // ill-conditioned): one plane with the mean of their normals
            // through the closest point, fixed for the rest of the solve.
            // (The mean normal with the distance to the surface as gap,
            // used before, converged linearly, by about 0.6 per step.)
            if (back && cross_product_3d(g.gradient, c.face.normal).norm() <
                          crease_sine)
              {
                Tensor<1, 3> normal = g.gradient + c.face.normal;
                c.held         = {Plane{normal / normal.norm(), current.point}};
                c.fixed_planes = true;
              }
            else if (back)
              {
                c.held = {current, c.face};
                ++c.plane_changes;
              }
            else
              {
                c.left.push_back(c.face);
                if (c.left.size() > 4)
                  c.left.erase(c.left.begin());
              }
          }
      }
    else if (std::abs(g.gap) > gap_tolerance &&
             std::none_of(c.held.begin(), c.held.end(), [&](const Plane &p) {
               return same(p.normal, g.gradient);
             }))
      {
        if (g.gap > 0)
          // Off the surface, held by planes whose faces it has slid past
          // (over a ridge): it follows the closest face again.
          {
            c.held.clear();
            ++c.plane_changes;
          }
        else
          {
            // Through another face: held too, if independent of the held
            // planes; otherwise it replaces the held plane closest to it.
            auto closest = c.held.begin();
            for (auto p = c.held.begin(); p != c.held.end(); ++p)
              if (p->normal * g.gradient > closest->normal * g.gradient)
                closest = p;
            const bool independent =
              c.held.size() == 1 ?
                cross_product_3d(closest->normal, g.gradient).norm() >
                  crease_sine :
              c.held.size() == 2 ?
                std::abs(cross_product_3d(c.held[0].normal, c.held[1].normal) *
                         g.gradient) > crease_sine * crease_sine :
                false;
            if (independent)
              c.held.push_back(current);
            else
              *closest = current;
            ++c.plane_changes;
          }
      }
    // A node whose planes keep changing (held, let go, held again; or two
    // faces replacing each other: 2-cycles seen with P2 at gravity x 10)
    // keeps its planes (or the closest face's) for the rest of the solve:
    // linear constraints that Newton meets exactly. It may then end a
    // little off the surface (fixed_plane_nodes() says how far). (A mean
    // normal with the distance to the surface as gap, used before,
    // converged linearly.)
    if (c.plane_changes > parameters.plane_changes)
      {
        if (c.held.empty())
          c.held = {current};
        c.fixed_planes = true;
      }
    update_gaps();
    if (c.held.empty())
      c.normal = g.gradient;
    else
      set_normal_from_held(c);
  }

  void
  ContactProblem::set_normal_from_held(Candidate &c)
  {
    Tensor<1, 3> sum;
    for (const Plane &p : c.held)
      sum += p.normal;
    c.normal = sum / sum.norm();
  }
} // namespace RestShape
