// The obstacle load that a load-carrying rest shape carries at the target
// (Inverse problem/Skull load share).
#ifndef restshape_inverse_carried_load_h
#define restshape_inverse_carried_load_h

#include <deal.II/base/tensor.h>

#include <restshape/contact/contact.h>
#include <restshape/forward/forward_problem.h>

#include <string>

namespace RestShape
{
  /// The reference contact solve and the forces it gives.
  struct CarriedLoad
  {
    bool         converged = false;
    std::string  failure;               // why the reference solve stopped
    unsigned int touching_nodes    = 0; // candidates on the obstacle at target
    unsigned int active_nodes      = 0; // of those, active in the reference
    unsigned int newton_iterations = 0;
    double       share             = 0;
    /// The obstacle's total force on the body in the reference solve, and
    /// share times that with the forces turned normal at the target (N).
    dealii::Tensor<1, 3> reference_force, stated_force;
    /// The stated nodal forces (owned, N): share max(0, lambda_i) n_i.
    VectorType forces;

    /// "Skull load: ..." (one line for the screen), or why it failed.
    std::string
    text() const;
  };

  /**
   * The reference of a load-carrying rest shape: the body, stress-free at
   * the target X + @p target_shift (the admissible target, owned, m),
   * settles under @p load onto the obstacle, with contact only at the
   * candidates that touch it at the target (ContactProblem::
   * AdmissibleTarget::keep_contacts()). Its contact forces, normal to the
   * obstacle at the target and times @p share, are what the obstacle carries in
   * the rest shape sought: the direct inverse then finds the rest shape whose
   * equilibrium at the target has exactly these obstacle forces. Leaves
   * the contact problem reset, every candidate back.
   */
  CarriedLoad
  carried_load(ForwardProblem   &forward,
               ContactProblem   &contact,
               const VectorType &target_shift,
               const LoadState  &load,
               const double      share);
} // namespace RestShape

#endif
