// The compressible one-term Ogden law.
#ifndef restshape_material_ogden_law_h
#define restshape_material_ogden_law_h

#include <restshape/material/material_law.h>

namespace RestShape
{
  /**
   * Compressible one-term Ogden hyperelasticity, the law fitted to brain
   * tissue (Budday et al. 2017; Bennion et al. 2022: mu = 670 Pa,
   * alpha = -19 for in vivo positional brain shift):
   *   W(F) = 2 mu / alpha^2 (sum_a s_a^alpha - 3 - alpha ln J)
   *          + lambda/2 (ln J)^2,
   * s_a the principal stretches (sum_a s_a^alpha = tr C^(alpha/2)),
   * J = det F, mu and lambda from the label's E and nu (the law equals
   * linear elasticity at small strain; alpha = 2 is the neo-Hookean law).
   *   P = F S_1 + (lambda ln J - 2 mu / alpha) F^-T,
   *   S_1 = 2 mu / alpha C^(alpha/2 - 1),
   * and the exact tangent through the derivative of the matrix function
   * S_1(C) (Daleckii-Krein: divided differences of its eigenvalues,
   * their derivative where two coincide). The warped tangent is the
   * exact one.
   */
  class OgdenLaw : public MaterialLaw
  {
  public:
    /// Its name, description and factory for the registry.
    static LawInfo
    info();

    /// alpha from the value of Materials/Ogden alpha (-19 if not given).
    explicit OgdenLaw(const LawParameters &parameters);
    /// Materials/Ogden alpha.
    static std::vector<LawParameter>
    parameters();

    bool
    evaluate(const Tensor2    &F,
             Tensor2          &P,
             Tensor4          *tangent,
             const TangentType type,
             double           *energy = nullptr) const override;

    /// The exponent alpha (nonzero).
    double alpha;
  };
} // namespace RestShape

#endif
