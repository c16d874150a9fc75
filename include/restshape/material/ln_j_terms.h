// The terms of the hyperelastic laws that depend on F only through ln J.
#ifndef restshape_material_ln_j_terms_h
#define restshape_material_ln_j_terms_h

#include <restshape/material/material_law.h>

namespace RestShape
{
  /**
   * For an energy c ln J + lambda/2 (ln J)^2 (the neo-Hookean and Ogden
   * laws), add to P its stress h F^-T and, if @p A is not null, to the
   * tangent its derivative
   *   lambda F^-T_iJ F^-T_kL - h F^-1_Jk F^-1_Li,   h = lambda ln J + c.
   */
  inline void
  add_ln_J_terms(const Tensor2 &F_inv,
                 const double   lambda,
                 const double   h,
                 Tensor2       &P,
                 Tensor4       *A)
  {
    const Tensor2 F_inv_T = transpose(F_inv);
    P += h * F_inv_T;
    if (A == nullptr)
      return;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J = 0; J < 3; ++J)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int L = 0; L < 3; ++L)
            (*A)[i][J][k][L] += lambda * F_inv_T[i][J] * F_inv_T[k][L] -
                                h * F_inv[J][k] * F_inv[L][i];
  }
} // namespace RestShape

#endif
