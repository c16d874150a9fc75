// Whether anything can hold the target: the loads' resultant against what
// the fixed labels, contact at the target and tethers can carry.
#ifndef restshape_inverse_load_path_h
#define restshape_inverse_load_path_h

#include <deal.II/base/tensor.h>

#include <restshape/loads/load_state.h>

#include <string>
#include <vector>

namespace RestShape
{
  class ForwardProblem;
  class ContactProblem;

  /**
   * The load path at the target (the mesh geometry, or the admissible
   * target with contact), by force balance alone: the resultant F of the
   * loads must be balanced by the obstacle's forces on the target's
   * contact nodes (each along its inward normal, pushing only) and by the
   * fixed labels. The part of F that no pushing combination of the contact
   * normals can balance (the distance from -F to their cone) goes through
   * the faces between fixed and free cells, of area A_c for component c:
   * it strains them by about |F_c| / (A_c E) (E: the largest Young's
   * modulus of the free cells). Moments are left out: a lower bound.
   * Tethers (an elastic support) can carry any load by moving: then the
   * path is not assessed.
   */
  struct LoadPath
  {
    /// Whether the path was assessed (false with an elastic support).
    bool assessed = false;
    /// The loads' resultant (N) and the part contact cannot carry (N).
    dealii::Tensor<1, 3> load, through_supports;
    /// Contact nodes of the target (on or beyond the obstacle).
    unsigned int contact_nodes = 0;
    /// Area (m^2) of the faces between fixed and free cells, per component.
    std::array<double, 3> support_area{{0, 0, 0}};
    /// The strain that load makes at those faces (infinite where a
    /// component carries load but nothing holds it).
    double strain = 0;

    /// "the loads' resultant (...) N ... strains them by about ..."
    std::string
    text() const;
    /// What a user can change, for a strain that no rest shape carries.
    static std::string
    remedy();
  };

  /// The load path of the scene's load @p load at the target (@p contact may
  /// be nullptr; @p target_shift: the admissible target's shift, owned).
  LoadPath
  assess_load_path(const ForwardProblem &forward,
                   const ContactProblem *contact,
                   const LoadState      &load);
} // namespace RestShape

#endif
