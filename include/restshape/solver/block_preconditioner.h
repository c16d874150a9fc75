// The block preconditioner of the mixed formulation: the block
// factorisation of the uncondensed system (PressureCoupling) applied to
// the condensed one. By the Sherman-Morrison-Woodbury identity
//
//   (A + G^T D^-1 G)^-1 = A^-1 - A^-1 G^T S^-1 G A^-1,  S = D + G A^-1 G^T,
//
// with AMG for A^-1 (the displacement block, whose stiffness is the shear
// modulus's, not the bulk modulus's) and the diagonal of
// D + G diag(A)^-1 G^T for S (PressureCoupling::inverse_schur_diagonal(),
// on a pressure per cell the pressure mass matrix scaled by 1/K + 1/mu).
// The Krylov method runs on the condensed system, so its residual is the
// Newton step's own.
#ifndef restshape_solver_block_preconditioner_h
#define restshape_solver_block_preconditioner_h

#include <deal.II/lac/trilinos_precondition.h>

#include <restshape/base/linear_algebra_types.h>
#include <restshape/solver/pressure_coupling.h>

namespace RestShape
{
  class BlockPreconditioner
  {
  public:
    /// With @p amg built on the displacement block and @p inverse_schur
    /// from @p coupling (all of which must outlive this object); without
    /// @p coupling, plain AMG (on the condensed tangent).
    BlockPreconditioner(const dealii::TrilinosWrappers::PreconditionAMG &amg,
                        const PressureCoupling *coupling,
                        const VectorType       &inverse_schur);

    /// dst = (A^-1 - A^-1 G^T S^-1 G A^-1) src: two AMG cycles (one
    /// without the coupling).
    void
    vmult(VectorType &dst, const VectorType &src) const;

  private:
    const dealii::TrilinosWrappers::PreconditionAMG &amg;
    const PressureCoupling                          *coupling;
    const VectorType                                &inverse_schur;
    mutable VectorType pressure, back, correction; // work vectors
  };
} // namespace RestShape

#endif
