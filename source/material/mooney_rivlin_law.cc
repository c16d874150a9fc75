#include <restshape/base/input_error.h>
#include <restshape/material/ln_j_terms.h>
#include <restshape/material/mooney_rivlin_law.h>

#include <cmath>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Half the shear modulus from each invariant by default.
    constexpr double  default_ratio = 0.5;
    const std::string ratio_name    = "Mooney-Rivlin ratio";
  } // namespace

  LawInfo
  MooneyRivlinLaw::info()
  {
    LawInfo i;
    i.name = "Mooney-Rivlin";
    i.description =
      "compressible two-term Mooney-Rivlin, W = C10 (I1 - 3) + C01 (I2 - 3) "
      "- 2 (C10 + 2 C01) ln J + lambda'/2 (ln J)^2, with C10 = (1 - r) mu/2, "
      "C01 = r mu/2 (r from Mooney-Rivlin ratio) and lambda' = lambda - 4 "
      "C01 (used for brain tissue beside Ogden: Mendis et al. 1995)";
    i.make       = law_factory<MooneyRivlinLaw>();
    i.parameters = MooneyRivlinLaw::parameters();
    return i;
  }

  MooneyRivlinLaw::MooneyRivlinLaw(const LawParameters &parameters)
    : MaterialLaw(parameters)
  {
    const double r = parameters.value(ratio_name, default_ratio);
    c10            = 0.5 * (1 - r) * mu;
    c01            = 0.5 * r * mu;
  }

  std::vector<LawParameter>
  MooneyRivlinLaw::parameters()
  {
    return {{ratio_name,
             number_text(default_ratio),
             "The part r of the shear modulus mu that the Mooney-Rivlin law "
             "carries by its second invariant (dimensionless, 0 <= r < 1): "
             "C10 = (1 - r) mu/2, C01 = r mu/2; one value or 'label:value' "
             "list (ranges and '*' as for Young's modulus). r = 0 is the "
             "neo-Hookean law. Used by labels whose Material law is "
             "Mooney-Rivlin.",
             "r",
             [](const double r) {
               return r >= 0 && r < 1 ? std::string() : "0 <= r < 1";
             }}};
  }

  bool
  MooneyRivlinLaw::evaluate(const Tensor2    &F,
                            Tensor2          &P,
                            Tensor4          *tangent,
                            const TangentType type,
                            double           *energy) const
  {
    const double J = determinant(F);
    if (!(J > 0))
      return false;
    const double  ln_J     = std::log(J);
    const Tensor2 C        = transpose(F) * F;
    const Tensor2 b        = F * transpose(F);
    const double  I1       = trace(C);
    const double  I2       = 0.5 * (I1 * I1 - scalar_product(C, C));
    const double  lambda_v = lambda - 4 * c01; // of the (ln J)^2 term
    // dI1/dF = 2 F, dI2/dF = 2 (I1 F - F C).
    P = 2 * c10 * F + 2 * c01 * (I1 * F - F * C);
    if (energy != nullptr)
      *energy = c10 * (I1 - 3) + c01 * (I2 - 3) - 2 * (c10 + 2 * c01) * ln_J +
                0.5 * lambda_v * ln_J * ln_J;
    if (tangent != nullptr)
      {
        Tensor4 &A = *tangent;
        A          = 0;
        // d^2 I1 = 2 d_ik d_JL; d^2 I2 = 2 (2 F_iJ F_kL + I1 d_ik d_JL
        // - d_ik C_LJ - F_iL F_kJ - b_ik d_JL).
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int J_ = 0; J_ < 3; ++J_)
            for (unsigned int k = 0; k < 3; ++k)
              for (unsigned int L = 0; L < 3; ++L)
                {
                  const double d_ik = (i == k), d_JL = (J_ == L);
                  A[i][J_][k][L] =
                    2 * c10 * d_ik * d_JL +
                    2 * c01 *
                      (2 * F[i][J_] * F[k][L] + I1 * d_ik * d_JL -
                       d_ik * C[L][J_] - F[i][L] * F[k][J_] - b[i][k] * d_JL);
                }
      }
    add_ln_J_terms(
      invert(F), lambda_v, lambda_v * ln_J - 2 * (c10 + 2 * c01), P, tangent);
    if (tangent != nullptr && type == TangentType::projected)
      project_negative_eigenvalues(*tangent);
    return true;
  }
} // namespace RestShape
