// The compressible two-term Mooney-Rivlin law.
#ifndef restshape_material_mooney_rivlin_law_h
#define restshape_material_mooney_rivlin_law_h

#include <restshape/material/material_law.h>

namespace RestShape
{
  /**
   * Compressible Mooney-Rivlin hyperelasticity (used for brain tissue beside
   * the Ogden law: Mendis et al. 1995, Miller's group; Bonet & Wood 6.5):
   *   W(F) = C10 (I1 - 3) + C01 (I2 - 3) - 2 (C10 + 2 C01) ln J
   *          + lambda'/2 (ln J)^2,
   * I1 = tr C, I2 = ((tr C)^2 - tr C^2)/2, C = F^T F, J = det F, with
   * C10 = (1 - r) mu/2, C01 = r mu/2 (r: Materials/Mooney-Rivlin ratio,
   * the part of the shear modulus the I2 term carries) and lambda' = lambda
   * - 4 C01, so that mu and lambda of the label's E and nu are the law's
   * small-strain moduli. r = 0 is the neo-Hookean law. The warped tangent
   * is the exact one.
   */
  class MooneyRivlinLaw : public MaterialLaw
  {
  public:
    /// Its name, description and factory for the registry.
    static LawInfo
    info();

    /// r from Materials/Mooney-Rivlin ratio (0.5 if not given).
    explicit MooneyRivlinLaw(const LawParameters &parameters);
    /// Materials/Mooney-Rivlin ratio.
    static std::vector<LawParameter>
    parameters();

    bool
    evaluate(const Tensor2    &F,
             Tensor2          &P,
             Tensor4          *tangent,
             const TangentType type,
             double           *energy = nullptr) const override;

    /// The coefficients of I1 - 3 and I2 - 3 (Pa).
    double c10, c01;
  };
} // namespace RestShape

#endif
