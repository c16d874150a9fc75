// The target the obstacle admits: a segmented skull may cut into the
// segmented brain, and what lies beyond it no equilibrium reaches. Before a
// solve: the obstacle's placement; for the inverse problem: the admissible
// target, its contact normals and forces, and the contacts it keeps.
#ifndef restshape_contact_admissible_target_h
#define restshape_contact_admissible_target_h

#include <deal.II/base/tensor.h>

#include <restshape/contact/contact.h>

#include <vector>

namespace RestShape
{
  /// The admissible target of a ContactProblem's candidates and obstacle.
  class AdmissibleTarget
  {
  public:
    /// The target of @p contact; keep_contacts() and restore_contacts()
    /// need it non-const.
    explicit AdmissibleTarget(ContactProblem &contact);
    explicit AdmissibleTarget(const ContactProblem &contact);

    /**
     * Check, before solving, that the obstacle is where the body is: throws
     * InputError (Contact/Obstacle file) with the counts and both bounding
     * boxes if more than Contact/Maximum outside fraction of the candidates
     * lie on the wrong side in the mesh geometry, or if every candidate is
     * farther from the obstacle than the body's size (no contact can occur:
     * an obstacle elsewhere, or in other units). @p shift (owned, m), if
     * given, moves the candidates first: from a rest shape that carries
     * its target to that target, which the obstacle must hold (a rest
     * shape may cross it).
     */
    void
    check_placement(const VectorType *shift = nullptr) const;

    /**
     * The admissible target: the mesh geometry with every contact
     * candidate that lies beyond the obstacle (by more than the gap
     * tolerance) moved onto it, to its closest point. Returns that move
     * (owned vector, m; zero at every other DoF): the part of the target
     * that no equilibrium can reach.
     */
    VectorType
    shift() const;

    /// The inward normals (towards the allowed side) of the candidates that
    /// touch the obstacle or lie beyond it in the mesh geometry (the
    /// contact nodes of the admissible target), from every rank.
    std::vector<dealii::Tensor<1, 3>>
    normals() const;

    /**
     * Until restore_contact(), only the candidates that touch the obstacle
     * at the target (the mesh geometry moved by @p target_shift, owned, m:
     * gap <= gap tolerance) may take contact; the others are removed as by
     * remove_contact(). Returns how many keep it (all ranks).
     */
    unsigned int
    keep_contacts(const VectorType &target_shift);
    /// Undo keep_target_contacts() (the openings of remove_contact() stay).
    void
    restore_contacts();
    /**
     * The obstacle's forces on the active nodes at the state of the last
     * update, turned normal to the obstacle at the target (the mesh
     * geometry moved by @p target_shift): max(0, lambda_i) n_i at the
     * node's DoFs (owned, N; zero elsewhere).
     */
    VectorType
    forces(const VectorType &raw_residual,
           const VectorType &target_shift) const;


  private:
    /// Part of check_placement() for Side = outside: no vertex of the
    /// obstacle lies inside the body (an obstacle inside it has no
    /// candidate on its wrong side, yet overlaps it). InputError naming
    /// the vertex otherwise.
    void
    check_obstacle_outside_body() const;
    /// Part of check_placement(): every vertex of a fixed label is on the
    /// allowed side, or less than @p depth (m) beyond it.
    void
    check_fixed_labels_enclosed(const double depth) const;

    const ContactProblem &contact;
    ContactProblem       *changeable = nullptr;
  };
} // namespace RestShape

#endif
