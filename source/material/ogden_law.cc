#include <deal.II/base/symmetric_tensor.h>

#include <restshape/base/input_error.h>
#include <restshape/material/ln_j_terms.h>
#include <restshape/material/ogden_law.h>

#include <array>
#include <cmath>

namespace RestShape
{
  using namespace dealii;

  LawInfo
  OgdenLaw::info()
  {
    LawInfo i;
    i.name = "Ogden";
    i.description =
      "compressible one-term Ogden, W = 2 mu/alpha^2 (sum of the principal "
      "stretches to the power alpha - 3 - alpha ln J) + lambda/2 (ln J)^2, "
      "with alpha from Ogden alpha (the brain's law: Budday et al. 2017)";
    i.make       = law_factory<OgdenLaw>();
    i.parameters = OgdenLaw::parameters();
    return i;
  }

  namespace
  {
    /// Eigenvalues below this relative difference count as equal (their
    /// divided difference becomes the derivative at their mean).
    constexpr double equal_eigenvalues = 1e-7;
    /// Bennion et al. 2022's fit to in vivo positional brain shift.
    constexpr double default_alpha = -19;
    /// stretch^alpha overflows beyond.
    constexpr double  max_alpha  = 100;
    const std::string alpha_name = "Ogden alpha";

    /// The spectral form of C: eigenvalues c_a and orthonormal vectors.
    struct Spectrum
    {
      std::array<double, 3>       c;
      std::array<Tensor<1, 3>, 3> n;
    };

    Spectrum
    spectrum(const Tensor2 &C)
    {
      const auto eig =
        eigenvectors(symmetrize(C), SymmetricTensorEigenvectorMethod::jacobi);
      Spectrum s;
      for (unsigned int a = 0; a < 3; ++a)
        {
          s.c[a] = eig[a].first;
          s.n[a] = eig[a].second;
        }
      return s;
    }
  } // namespace

  OgdenLaw::OgdenLaw(const LawParameters &parameters)
    : MaterialLaw(parameters)
    , alpha(parameters.value(alpha_name, default_alpha))
  {}

  std::vector<LawParameter>
  OgdenLaw::parameters()
  {
    return {{alpha_name,
             number_text(default_alpha),
             "The exponent alpha of the Ogden law (dimensionless, "
             "nonzero, |alpha| <= 100): one value or 'label:value' "
             "list (ranges and '*' as for Young's modulus). "
             "Negative values stiffen the tissue in compression "
             "more than in tension, as brain tissue does (alpha = "
             "-19 with mu = 670 Pa fits in vivo positional brain "
             "shift, Bennion et al. 2022); alpha = 2 is the "
             "neo-Hookean law. Used by labels whose Material law "
             "is Ogden.",
             "alpha",
             [](const double a) {
               return a != 0 && std::abs(a) <= max_alpha ?
                        std::string() :
                        "a nonzero exponent with |alpha| <= " +
                          number_text(max_alpha);
             }}};
  }

  bool
  OgdenLaw::evaluate(const Tensor2    &F,
                     Tensor2          &P,
                     Tensor4          *tangent,
                     const TangentType type,
                     double           *energy) const
  {
    const double J = determinant(F);
    if (!(J > 0))
      return false;
    const double   ln_J  = std::log(J);
    const Tensor2  F_inv = invert(F);
    const Spectrum s     = spectrum(transpose(F) * F);
    // phi(c) = 2 mu / alpha c^(alpha/2 - 1), S_1 = phi(C).
    const double beta = alpha / 2 - 1;
    const auto   phi  = [&](const double c) {
      return 2 * mu / alpha * std::pow(c, beta);
    };
    std::array<double, 3> phi_a;
    Tensor2               S1;
    double                sum_powers = 0;
    for (unsigned int a = 0; a < 3; ++a)
      {
        if (!(s.c[a] > 0))
          return false;
        phi_a[a] = phi(s.c[a]);
        S1 += phi_a[a] * outer_product(s.n[a], s.n[a]);
        sum_powers += std::pow(s.c[a], alpha / 2);
      }
    const double h = lambda * ln_J - 2 * mu / alpha;
    P              = F * S1;
    if (energy != nullptr)
      *energy = 2 * mu / (alpha * alpha) * (sum_powers - 3 - alpha * ln_J) +
                0.5 * lambda * ln_J * ln_J;
    if (tangent == nullptr)
      {
        add_ln_J_terms(F_inv, lambda, h, P, nullptr);
        return true;
      }

    // Divided differences of phi over the eigenvalues of C.
    Tensor2 D;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        {
          const double gap = s.c[a] - s.c[b];
          if (std::abs(gap) > equal_eigenvalues * (s.c[a] + s.c[b]))
            D[a][b] = (phi_a[a] - phi_a[b]) / gap;
          else
            D[a][b] =
              beta * phi(0.5 * (s.c[a] + s.c[b])) / (0.5 * (s.c[a] + s.c[b]));
        }
    Tensor2 N; // columns: the eigenvectors
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int i = 0; i < 3; ++i)
        N[i][a] = s.n[a][i];
    Tensor4 &A = *tangent;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int L = 0; L < 3; ++L)
        {
          // dF = e_k e_L^T: dC = F^T dF + dF^T F, dS_1 = N (D o N^T dC N) N^T.
          Tensor2 dC;
          for (unsigned int Q = 0; Q < 3; ++Q)
            {
              dC[L][Q] += F[k][Q];
              dC[Q][L] += F[k][Q];
            }
          Tensor2 M = transpose(N) * dC * N;
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = 0; b < 3; ++b)
              M[a][b] *= D[a][b];
          const Tensor2 dS1 = N * M * transpose(N);
          Tensor2       dP  = F * dS1;
          for (unsigned int J_ = 0; J_ < 3; ++J_)
            dP[k][J_] += S1[L][J_];
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int J_ = 0; J_ < 3; ++J_)
              A[i][J_][k][L] = dP[i][J_];
        }
    add_ln_J_terms(F_inv, lambda, h, P, tangent);
    if (type == TangentType::projected)
      project_negative_eigenvalues(A);
    return true;
  }
} // namespace RestShape
