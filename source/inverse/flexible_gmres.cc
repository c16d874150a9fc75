// FlexibleGmres: Saad's FGMRES with Givens rotations (see flexible_gmres.h).
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <restshape/inverse/flexible_gmres.h>

#include <cmath>
#include <vector>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// One Givens rotation, zeroing the second of (a, b).
    struct Rotation
    {
      double c = 1, s = 0;

      void
      apply(double &a, double &b) const
      {
        const double t = c * a + s * b;
        b              = -s * a + c * b;
        a              = t;
      }
    };

    Rotation
    rotation_zeroing(const double a, const double b)
    {
      const double r = std::hypot(a, b);
      return r == 0 ? Rotation() : Rotation{a / r, b / r};
    }
  } // namespace

  FlexibleGmres::FlexibleGmres(const unsigned int max_iterations)
    : max_iterations(max_iterations)
  {}

  FlexibleGmresResult
  FlexibleGmres::solve(const Operator   &A,
                       const Operator   &preconditioner,
                       VectorType       &x,
                       const VectorType &b,
                       const double      tolerance) const
  {
    FlexibleGmresResult result;
    x               = 0;
    result.residual = b.l2_norm();
    if (result.residual <= tolerance)
      return result;

    std::vector<VectorType> V{b}, Z;
    V[0] /= result.residual;
    FullMatrix<double>    H(max_iterations + 1, max_iterations);
    std::vector<Rotation> rotations;
    Vector<double>        g(max_iterations + 1);
    g(0) = result.residual;
    for (unsigned int j = 0; j < max_iterations; ++j)
      {
        Z.emplace_back(b);
        preconditioner(Z[j], V[j]);
        VectorType w(b);
        A(w, Z[j]);
        // Arnoldi, modified Gram-Schmidt.
        for (unsigned int i = 0; i <= j; ++i)
          {
            H(i, j) = w * V[i];
            w.add(-H(i, j), V[i]);
          }
        H(j + 1, j) = w.l2_norm();
        for (unsigned int i = 0; i < j; ++i)
          rotations[i].apply(H(i, j), H(i + 1, j));
        const double breakdown = H(j + 1, j);
        rotations.push_back(rotation_zeroing(H(j, j), H(j + 1, j)));
        rotations[j].apply(H(j, j), H(j + 1, j));
        rotations[j].apply(g(j), g(j + 1));
        result.iterations = j + 1;
        result.residual   = std::abs(g(j + 1));
        if (result.residual <= tolerance || breakdown == 0)
          break;
        w /= breakdown;
        V.push_back(std::move(w));
      }

    // x = Z y with H y = g (upper triangular after the rotations).
    const unsigned int  k = result.iterations;
    std::vector<double> y(k);
    for (unsigned int i = k; i-- > 0;)
      {
        double sum = g(i);
        for (unsigned int l = i + 1; l < k; ++l)
          sum -= H(i, l) * y[l];
        y[i] = H(i, i) != 0 ? sum / H(i, i) : 0.;
        x.add(y[i], Z[i]);
      }
    return result;
  }
} // namespace RestShape
