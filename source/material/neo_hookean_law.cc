#include <deal.II/base/symmetric_tensor.h>

#include <restshape/material/ln_j_terms.h>
#include <restshape/material/neo_hookean_law.h>

#include <cmath>

namespace RestShape
{
  using namespace dealii;

  LawInfo
  NeoHookeanLaw::info()
  {
    LawInfo i;
    i.name = "neo-Hookean";
    i.description =
      "compressible neo-Hookean, W = mu/2 (tr C - 3) - mu ln J + lambda/2 "
      "(ln J)^2 (its energy grows without bound as a cell collapses: for "
      "strains of order one)";
    i.make = law_factory<NeoHookeanLaw>();
    return i;
  }

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
    const double ln_J = std::log(J);
    P                 = mu * F;
    if (energy != nullptr)
      *energy = 0.5 * mu * (F.norm_square() - 3) - mu * ln_J +
                0.5 * lambda * ln_J * ln_J;
    if (tangent != nullptr)
      {
        *tangent = 0;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int J_ = 0; J_ < 3; ++J_)
            (*tangent)[i][J_][i][J_] = mu;
      }
    add_ln_J_terms(invert(F), lambda, lambda * ln_J - mu, P, tangent);
    if (tangent != nullptr && type == TangentType::projected)
      project_negative_eigenvalues(*tangent);
    return true;
  }
} // namespace RestShape
