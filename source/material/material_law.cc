#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <restshape/material/material_law.h>

#include <limits>

namespace RestShape
{
  using namespace dealii;

  MaterialLaw::MaterialLaw(const LawParameters &p)
    : mu(p.youngs_modulus / (2 * (1 + p.poissons_ratio)))
    , lambda(p.youngs_modulus * p.poissons_ratio /
             ((1 + p.poissons_ratio) * (1 - 2 * p.poissons_ratio)))
  {}

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
