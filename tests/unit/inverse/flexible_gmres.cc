// FlexibleGmres against a known solution on a nonsymmetric matrix (a 1d
// convection-diffusion stencil): without a preconditioner, with one that
// changes from one application to the next (flexible), with an exact one
// (one iteration), a zero right-hand side (no product) and a capped
// iteration count. Each check compares GMRES's residual estimate with the
// true |b - A x|, and the solve stops at the product that meets the
// tolerance: with one iteration less it would not have.
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>
#include <restshape/inverse/flexible_gmres.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "banded_matrix.h"
#include "checks.h"

using namespace dealii;
using namespace RestShape;
using checks::expect;

namespace
{
  constexpr unsigned int n = 200;

  std::string
  text(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(3) << x;
    return s.str();
  }

  /// |b - A x|.
  double
  true_residual(const MatrixType &A, const VectorType &x, const VectorType &b)
  {
    VectorType r(b);
    A.vmult(r, x);
    r.sadd(-1., 1., b);
    return r.l2_norm();
  }

  /// Solve with @p P to @p tolerance (relative to |b|) and check the
  /// estimate, the error, the product count and the stop.
  void
  check(const std::string             &what,
        const MatrixType              &A,
        const FlexibleGmres::Operator &P,
        const VectorType              &x_true,
        const double                   tolerance,
        const unsigned int             expected_iterations = 0)
  {
    VectorType b(x_true), x(x_true);
    A.vmult(b, x_true);
    unsigned int                  products = 0;
    const FlexibleGmres::Operator A_op     = [&](VectorType       &dst,
                                             const VectorType &src) {
      ++products;
      A.vmult(dst, src);
    };
    const double absolute = tolerance * b.l2_norm();
    const auto   result   = FlexibleGmres(n).solve(A_op, P, x, b, absolute);
    const double residual = true_residual(A, x, b);
    expect(residual <= 1.001 * absolute &&
             std::abs(residual - result.residual) <= 1e-6 * b.l2_norm(),
           what + ": |b - Ax| " + text(residual / b.l2_norm()) +
             " |b| meets the tolerance, as estimated");
    expect(products == result.iterations,
           what + ": one product per iteration (" + std::to_string(products) +
             ")");
    if (expected_iterations > 0)
      expect(result.iterations == expected_iterations,
             what + ": " + std::to_string(result.iterations) +
               " iterations, expected " + std::to_string(expected_iterations));
    if (result.iterations > 1)
      {
        VectorType y(x);
        const auto fewer =
          FlexibleGmres(result.iterations - 1).solve(A_op, P, y, b, absolute);
        expect(fewer.residual > absolute && true_residual(A, y, b) > absolute,
               what + ": one iteration less does not meet it");
      }
    x -= x_true;
    expect(x.l2_norm() <= 1e3 * tolerance * x_true.l2_norm(),
           what + ": the error follows the residual");
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const IndexSet                   all = complete_index_set(n);
  MatrixType                       A, D;
  checks::reinit_banded(A, n, 1);
  checks::reinit_banded(D, n, 1);
  for (unsigned int i = 0; i < n; ++i)
    {
      A.set(i, i, 2.5 + 0.01 * i);
      D.set(i, i, 1. + i);
      if (i + 1 < n)
        {
          A.set(i, i + 1, -1.3); // convection: nonsymmetric
          A.set(i + 1, i, -0.7);
        }
    }
  A.compress(VectorOperation::insert);
  D.compress(VectorOperation::insert);
  VectorType x_true(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < n; ++i)
    x_true[i] = std::sin(0.1 * i) + 0.01 * i;

  const FlexibleGmres::Operator identity =
    [](VectorType &dst, const VectorType &src) { dst = src; };
  check("no preconditioner", A, identity, x_true, 1e-10);

  // Jacobi, scaled differently at every application: not a fixed operator.
  unsigned int                  applications = 0;
  const FlexibleGmres::Operator varying      = [&](VectorType       &dst,
                                              const VectorType &src) {
    const double scale = (applications++ % 2 == 0) ? 1. : 0.3;
    for (const auto i : dst.locally_owned_elements())
      dst[i] = scale * src[i] / A.diag_element(i);
    dst.compress(VectorOperation::insert);
  };
  check("varying preconditioner", A, varying, x_true, 1e-8);

  // The exact inverse of a diagonal matrix: one iteration.
  const FlexibleGmres::Operator exact = [&](VectorType       &dst,
                                            const VectorType &src) {
    for (const auto i : dst.locally_owned_elements())
      dst[i] = src[i] / D.diag_element(i);
    dst.compress(VectorOperation::insert);
  };
  check("exact preconditioner", D, exact, x_true, 1e-12, 1);

  // A zero right-hand side: x = 0 without a product.
  {
    VectorType   b(x_true), x(x_true);
    unsigned int products = 0;
    b                     = 0;
    const auto result     = FlexibleGmres(n).solve(
      [&](VectorType &dst, const VectorType &src) {
        ++products;
        A.vmult(dst, src);
      },
      identity,
      x,
      b,
      1e-12);
    expect(result.iterations == 0 && products == 0 && x.l2_norm() == 0,
           "zero right-hand side: x = 0, no product");
  }

  // Capped: the best x in the space built, its residual as estimated.
  {
    VectorType b(x_true), x(x_true);
    A.vmult(b, x_true);
    const auto result =
      FlexibleGmres(5).solve([&](VectorType       &dst,
                                 const VectorType &src) { A.vmult(dst, src); },
                             identity,
                             x,
                             b,
                             1e-14 * b.l2_norm());
    const double residual = true_residual(A, x, b);
    expect(result.iterations == 5 && residual < b.l2_norm() &&
             std::abs(residual - result.residual) <= 1e-10 * b.l2_norm(),
           "capped at 5 iterations: residual " + text(residual / b.l2_norm()) +
             " |b|, as estimated, below |b|");
  }
  return checks::failures == 0 ? 0 : 1;
}
