// What the contact of a solve carries and where, at the state of its last
// active-set update: counts, forces (total and by label), pressures, the
// contact zone, and the nodal fields for output.
#ifndef restshape_contact_contact_report_h
#define restshape_contact_contact_report_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/contact/contact.h>

#include <map>
#include <utility>

namespace RestShape
{
  /// The results of a ContactProblem (read-only; a view of its candidates).
  class ContactReport
  {
  public:
    explicit ContactReport(const ContactProblem &contact);

    unsigned int
    n_active() const;
    /// Active nodes that hold the planes of two or three faces (creases and
    /// corners of the obstacle's triangulation).
    unsigned int
    n_held() const;
    /// Active nodes whose planes kept changing and are fixed for the rest of
    /// the solve, and the largest distance of one of them from the obstacle
    /// surface (m): they meet their planes' constraints, not the surface's.
    std::pair<unsigned int, double>
    fixed_plane_nodes() const;
    /// Active nodes whose own contact force pulls on the obstacle (accepted
    /// below 0.1 % of the contact force, or as grazing, or when the thaws
    /// ran out): how many, their summed pull (N) and its ratio to the summed
    /// push of the others.
    struct Adhesion
    {
      unsigned int nodes    = 0;
      double       force    = 0;
      double       fraction = 0;
    };
    Adhesion
    adhesion(const VectorType &raw_residual) const;
    /// Sum of the obstacle's forces on the body (N).
    dealii::Tensor<1, 3>
    total_force(const VectorType &raw_residual) const;
    /// The same force by label (N, every label of the mesh): an active
    /// node's force counts for the labels of the cells around it, in equal
    /// shares; the shares add up to total_force().
    std::map<Label, dealii::Tensor<1, 3>>
    force_by_label(const VectorType &raw_residual) const;
    /// Largest penetration (-gap) of an eligible node (m), and of any node.
    double
    max_penetration(const bool eligible_only) const;
    /**
     * Per node: x slot 1 for active nodes, y slot the gap (in metres times
     * @p length_scale), z slot the recovered contact pressure (Pa,
     * recovered_pressures()).
     */
    VectorType
    nodal_fields(const VectorType &raw_residual,
                 const double      length_scale) const;
    /// Smallest and largest contact pressure over active nodes (Pa).
    std::pair<double, double>
    pressure_range(const VectorType &raw_residual) const;
    /// Largest distance of an active node from the axis through @p point
    /// along @p direction (m): the radius of the contact zone.
    double
    contact_radius(const dealii::Point<3>     &point,
                   const dealii::Tensor<1, 3> &direction) const;
    /// contact_radius() about the axis through the centroid of the active
    /// nodes along @p direction (m; 0 without active nodes): the radius of
    /// a contact patch whose centre is not known in advance.
    double
    patch_radius(const dealii::Tensor<1, 3> &direction) const;
    unsigned int
    n_candidates() const;
    /// Surface faces on the walls of cavities inside the body, which are
    /// not candidates.
    unsigned int
    n_cavity_wall_faces() const;
    /// Candidates beyond the obstacle (gap < -g_tol), eligible or not.
    unsigned int
    n_outside() const;


    /**
     * The contact pressure as a field (Pa, per candidate; owned entries):
     * each node's contact force is shared among the surface faces around
     * it that face the obstacle, in proportion to their lumped areas at
     * the node; each face's traction is what it received over its area;
     * a node's pressure is the area-weighted mean of its faces' tractions
     * (the force over its lumped area where no face around it faces the
     * obstacle). A uniform pressure is exact, the total force is kept
     * (sum of the faces' tractions times their areas), and a node that
     * carries the force of a larger region than its own area (at the rim
     * of a contact zone, on the crease of a faceted skull) shares it with
     * its faces instead of showing it as a single-node peak. Zero at
     * inactive nodes.
     */
    std::vector<double>
    recovered_pressures(const VectorType &raw_residual) const;

  private:
    /// Contact pressure of every candidate (Pa; 0 where inactive): its
    /// force over its share of the faces around it.
    std::vector<double>
    pressures(const VectorType &raw_residual) const;

    const ContactProblem &contact;
  };
} // namespace RestShape

#endif
