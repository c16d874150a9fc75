#include <deal.II/base/symmetric_tensor.h>

#include <restshape/forward/neo_hookean_law.h>

#include <cmath>

namespace RestShape
{
  using namespace dealii;

  NeoHookeanLaw::NeoHookeanLaw(const LawParameters &parameters)
    : MaterialLaw(parameters)
  {}

  bool
  NeoHookeanLaw::evaluate(const Tensor2    &F,
                          Tensor2          &P,
                          Tensor4          *tangent,
                          const TangentType type,
                          double           *energy) const
  {
    const double J = determinant(F);
    if (!(J > 0))
      return false;
    const double  ln_J    = std::log(J);
    const Tensor2 F_inv   = invert(F);
    const Tensor2 F_inv_T = transpose(F_inv);
    P                     = mu * (F - F_inv_T) + lambda * ln_J * F_inv_T;
    if (energy != nullptr)
      *energy = 0.5 * mu * (F.norm_square() - 3) - mu * ln_J +
                0.5 * lambda * ln_J * ln_J;
    if (tangent == nullptr)
      return true;
    Tensor4     &A = *tangent;
    const double c = mu - lambda * ln_J;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J_ = 0; J_ < 3; ++J_)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int L = 0; L < 3; ++L)
            A[i][J_][k][L] = (i == k && J_ == L ? mu : 0.) +
                             lambda * F_inv_T[i][J_] * F_inv_T[k][L] +
                             c * F_inv[L][i] * F_inv[J_][k];
    if (type == TangentType::projected)
      project_negative_eigenvalues(A);
    return true;
  }
} // namespace RestShape
