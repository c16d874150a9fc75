// The planes an active contact node holds in a crease or corner of the
// triangulated obstacle while the active set only grows.
#ifndef restshape_held_planes_h
#define restshape_held_planes_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/contact/obstacle.h>

#include <vector>

namespace RestShape
{
  /// The plane of an obstacle face: unit normal towards the allowed side,
  /// a point on it (m), and a node's signed distance from it (m).
  struct ContactPlane
  {
    dealii::Tensor<1, 3> normal;
    dealii::Point<3>     point;
    double               gap = 0;
  };

  /**
   * The crease logic of one active contact node. An active node takes the
   * exact gradient of the gap as its normal, so Newton converges
   * quadratically while it stays on one face. A node that comes back to a
   * face it has left rests in a crease of the triangulated surface, where
   * the closest face alternates (2- and 3-cycles; at heavy load most
   * contact nodes of the brain). It then holds the planes of both faces at
   * once, so it slides along the crease, and its constraints are linear:
   * quadratic convergence again. A held node that goes through a third,
   * independent face holds that one too (a corner). A node whose planes
   * keep changing more than a given number of times keeps them for the
   * rest of the solve (fixed planes: linear constraints that Newton meets
   * exactly; it may then end a little off the surface).
   */
  class HeldPlanes
  {
  public:
    /// Two unit normals closer than this are the same face's.
    static constexpr double same_normal_tolerance = 1e-6;
    /// Faces whose normals differ by less than this angle (degrees) make
    /// one plane with their mean normal: two would be ill-conditioned.
    static constexpr double crease_angle_degrees = 10;
    /// How many faces left since the last change a node remembers.
    static constexpr unsigned int faces_remembered = 4;

    /**
     * Follow the node, now at @p x (m) with closest face @p g, while
     * releases are frozen. Faces are told apart by their normals; the gap
     * tolerance (m) says when the node is off its planes; after more than
     * @p max_changes changes the planes are fixed. Sets @p normal to the
     * node's new normal unless the planes were already fixed.
     */
    void
    update(const dealii::Point<3> &x,
           const Gap              &g,
           const double            gap_tolerance,
           const unsigned int      max_changes,
           dealii::Tensor<1, 3>   &normal);

    /// Remember the closest face of the node at @p x (every update).
    void
    set_closest_face(const dealii::Point<3> &x, const Gap &g);

    /// Forget the planes and the locks (a node that is not active while
    /// releases are frozen, or one that left its planes).
    void
    let_go();

    /// Forget everything, the closest face too (a new solve).
    void
    reset();

    /// Let go of the planes whose bits are set in @p mask. Returns whether
    /// the node's normal (normal()) has to follow.
    bool
    drop(const unsigned int mask);

    /// The mean of the held planes' normals (unit).
    dealii::Tensor<1, 3>
    normal() const;

    const std::vector<ContactPlane> &
    planes() const
    {
      return held;
    }

    /// Whether the planes are fixed for the rest of the solve.
    bool
    fixed() const
    {
      return fixed_planes;
    }

    /// For fixed planes: the plane through their mean point with their
    /// mean normal (imposed when the planes themselves cannot be).
    const ContactPlane &
    mean_plane() const
    {
      return mean;
    }

    /// The gap of the held planes farthest from 0 (m), or the mean
    /// plane's if @p mean_imposed.
    double
    constrained_gap(const bool mean_imposed) const;

  private:
    static bool
    same(const dealii::Tensor<1, 3> &a, const dealii::Tensor<1, 3> &b);
    /// Whether @p normal is that of a held plane.
    bool
    holds(const dealii::Tensor<1, 3> &normal) const;
    /// No plane held: a node back on a face it left holds a crease.
    void
    follow_faces(const ContactPlane &current, const Gap &g);
    /// Planes held and the node off them onto another face.
    void
    meet_face(const ContactPlane &current, const Gap &g);
    /// The held planes' (and the mean plane's) gaps at @p x.
    void
    update_gaps(const dealii::Point<3> &x);

    ContactPlane              face; // the closest face at the last update
    std::vector<ContactPlane> left, held;
    bool                      fixed_planes = false;
    unsigned int              changes      = 0;
    ContactPlane              mean;
  };
} // namespace RestShape

#endif
