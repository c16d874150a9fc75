#include <restshape/solver/block_preconditioner.h>

namespace RestShape
{
  using namespace dealii;

  BlockPreconditioner::BlockPreconditioner(
    const TrilinosWrappers::PreconditionAMG &amg,
    const PressureCoupling                  *coupling,
    const VectorType                        &inverse_schur)
    : amg(amg)
    , coupling(coupling)
    , inverse_schur(inverse_schur)
  {}

  void
  BlockPreconditioner::vmult(VectorType &dst, const VectorType &src) const
  {
    // y = A^-1 src; dp = S^-1 G y; dst = y - A^-1 G^T dp.
    amg.vmult(dst, src);
    if (coupling == nullptr)
      return;
    if (back.size() != src.size())
      {
        pressure.reinit(inverse_schur, true);
        back.reinit(src, true);
        correction.reinit(src, true);
      }
    coupling->rows().vmult(pressure, dst);
    pressure.scale(inverse_schur);
    coupling->rows().Tvmult(back, pressure);
    amg.vmult(correction, back);
    dst -= correction;
  }
} // namespace RestShape
