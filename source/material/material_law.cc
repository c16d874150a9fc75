#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <restshape/material/material_law.h>

#include <cmath>
#include <limits>

namespace RestShape
{
  using namespace dealii;

  MaterialLaw::MaterialLaw(const LawParameters &p)
    : mu(p.youngs_modulus / (2 * (1 + p.poissons_ratio)))
    , lambda(p.youngs_modulus * p.poissons_ratio /
             ((1 + p.poissons_ratio) * (1 - 2 * p.poissons_ratio)))
    , bulk_modulus(p.youngs_modulus / (3 * (1 - 2 * p.poissons_ratio)))
  {}

  bool
  MaterialLaw::evaluate_isochoric(const Tensor2    &F,
                                  Tensor2          &P,
                                  Tensor4          *tangent,
                                  const TangentType type,
                                  double           *energy) const
  {
    const double J = determinant(F);
    if (!(J > 0))
      return false;
    // W_iso(F) = W(G F), G = J^-1/3: with Pb = dW/dF at G F and
    // s = Pb : F, P = G (Pb - s/3 F^-T).
    const double      G       = std::cbrt(1 / J);
    const Tensor2     F_inv_T = transpose(invert(F));
    Tensor2           Pb;
    Tensor4           Ab;
    const TangentType inner =
      type == TangentType::projected ? TangentType::consistent : type;
    if (!evaluate(G * F, Pb, tangent != nullptr ? &Ab : nullptr, inner, energy))
      return false;
    const double s = scalar_product(Pb, F);
    P              = G * (Pb - (s / 3) * F_inv_T);
    if (tangent == nullptr)
      return true;
    // d(G F)_aB / dF_kL = G (d_ak d_BL - F_aB F^-T_kL / 3), so
    // dPb_iJ/dF_kL = G (Ab_iJkL - (Ab_iJ : F) F^-T_kL / 3),
    // ds/dF_kL = G ((F : Ab)_kL - (F : Ab : F) F^-T_kL / 3) + Pb_kL,
    // dG/dF_kL = -G F^-T_kL / 3, dF^-T_iJ/dF_kL = -F^-T_iL F^-T_kJ.
    Tensor2 AbF, FAb; // Ab_iJ : F and F : Ab_kL
    double  FAbF = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J_ = 0; J_ < 3; ++J_)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int L = 0; L < 3; ++L)
            {
              AbF[i][J_] += Ab[i][J_][k][L] * F[k][L];
              FAb[k][L] += F[i][J_] * Ab[i][J_][k][L];
            }
    FAbF            = scalar_product(FAb, F);
    Tensor4      &A = *tangent;
    const Tensor2 Q = Pb - (s / 3) * F_inv_T; // P / G
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J_ = 0; J_ < 3; ++J_)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int L = 0; L < 3; ++L)
            {
              const double dPb =
                G * (Ab[i][J_][k][L] - AbF[i][J_] * F_inv_T[k][L] / 3);
              const double ds =
                G * (FAb[k][L] - FAbF * F_inv_T[k][L] / 3) + Pb[k][L];
              A[i][J_][k][L] = -G * F_inv_T[k][L] / 3 * Q[i][J_] +
                               G * (dPb - ds / 3 * F_inv_T[i][J_] +
                                    s / 3 * F_inv_T[i][L] * F_inv_T[k][J_]);
            }
    if (type == TangentType::projected)
      project_negative_eigenvalues(A);
    return true;
  }

  MaterialLaw::Volumetric
  MaterialLaw::volumetric(const double J) const
  {
    const double ln_J = std::log(J);
    return {0.5 * bulk_modulus * ln_J * ln_J,
            bulk_modulus * ln_J / J,
            bulk_modulus * (1 - ln_J) / (J * J)};
  }

  double
  MaterialLaw::energy_density(const Tensor2 &F) const
  {
    Tensor2 P;
    double  W = std::numeric_limits<double>::infinity();
    evaluate(F, P, nullptr, TangentType::warped, &W);
    return W;
  }

  void
  project_negative_eigenvalues(Tensor4 &A)
  {
    constexpr unsigned int   n = 9;
    LAPACKFullMatrix<double> M(n, n);
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = 0; b < n; ++b)
        M(a, b) =
          0.5 * (A[a / 3][a % 3][b / 3][b % 3] + A[b / 3][b % 3][a / 3][a % 3]);
    Vector<double>     values;
    FullMatrix<double> vectors;
    M.compute_eigenvalues_symmetric(-std::numeric_limits<double>::max(),
                                    std::numeric_limits<double>::max(),
                                    0.,
                                    values,
                                    vectors);
    for (unsigned int m = 0; m < values.size(); ++m)
      if (values[m] < 0)
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            A[a / 3][a % 3][b / 3][b % 3] -=
              values[m] * vectors(a, m) * vectors(b, m);
  }
} // namespace RestShape
