#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <restshape/inverse/anderson.h>

namespace RestShape
{
  using namespace dealii;

  AndersonAccelerator::AndersonAccelerator(const unsigned int depth)
    : depth(depth)
  {}

  void
  AndersonAccelerator::reset()
  {
    dX.clear();
    dF.clear();
    has_last = false;
    used     = 0;
  }

  unsigned int
  AndersonAccelerator::columns_used() const
  {
    return used;
  }

  VectorType
  AndersonAccelerator::next(const VectorType &x, const VectorType &f)
  {
    if (has_last)
      {
        VectorType dx = x, df = f;
        dx -= x_last;
        df -= f_last;
        dX.push_back(dx);
        dF.push_back(df);
        if (dX.size() > depth)
          {
            dX.pop_front();
            dF.pop_front();
          }
      }
    x_last   = x;
    f_last   = f;
    has_last = true;

    VectorType result = x;
    result += f;
    // Least squares on the newest columns; drop the oldest while the Gram
    // matrix is too ill-conditioned to trust.
    while (!dF.empty())
      {
        const unsigned int m = dF.size();
        FullMatrix<double> gram(m, m);
        Vector<double>     rhs(m), gamma(m);
        double             trace = 0;
        for (unsigned int i = 0; i < m; ++i)
          {
            for (unsigned int j = 0; j <= i; ++j)
              gram(i, j) = gram(j, i) = dF[i] * dF[j];
            rhs(i) = dF[i] * f;
            trace += gram(i, i);
          }
        if (trace == 0)
          break;
        for (unsigned int i = 0; i < m; ++i)
          gram(i, i) += 1e-12 * trace;
        FullMatrix<double> inverse(m, m);
        inverse.invert(gram);
        inverse.vmult(gamma, rhs);
        // Condition estimate: |G| |G^-1| in the Frobenius norm.
        if (gram.frobenius_norm() * inverse.frobenius_norm() > 1e10 && m > 1)
          {
            dX.pop_front();
            dF.pop_front();
            continue;
          }
        for (unsigned int i = 0; i < m; ++i)
          {
            result.add(-gamma(i), dX[i]);
            result.add(-gamma(i), dF[i]);
          }
        used = m;
        return result;
      }
    used = 0;
    return result;
  }
} // namespace RestShape
