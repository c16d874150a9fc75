// The compressible neo-Hookean law.
#ifndef restshape_material_neo_hookean_law_h
#define restshape_material_neo_hookean_law_h

#include <restshape/material/material_law.h>

namespace RestShape
{
  /**
   * Compressible neo-Hookean hyperelasticity (Ogden 1984; Bonet & Wood,
   * "Nonlinear continuum mechanics for finite element analysis", 6.4.3):
   *   W(F) = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
   *   P    = mu (F - F^-T) + lambda ln J F^-T,
   *   dP_iJ/dF_kL = mu d_ik d_JL + lambda F^-T_iJ F^-T_kL
   *                 + (mu - lambda ln J) F^-1_Li F^-1_Jk,
   * with C = F^T F, J = det F and mu, lambda the Lame parameters of the
   * label's E and nu (the law equals linear elasticity at small strain).
   * Unlike the co-rotational law its energy grows without bound as J goes
   * to 0, so cells resist collapse: large compressive strains (the brain
   * under its full weight) keep a solution. The warped tangent is the
   * exact one.
   */
  class NeoHookeanLaw : public MaterialLaw
  {
  public:
    /// Its name, description and factory for the registry.
    static LawInfo
    info();

    explicit NeoHookeanLaw(const LawParameters &parameters);

    bool
    evaluate(const Tensor2    &F,
             Tensor2          &P,
             Tensor4          *tangent,
             const TangentType type,
             double           *energy = nullptr) const override;
  };
} // namespace RestShape

#endif
