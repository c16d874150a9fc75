// MUMPS's LDL^T (SymmetricMumps, taken by LinearSolver with Direct
// factorisation = ldlt for a symmetric matrix on one process) against a known
// solution and against Amesos's LU (set_symmetric(false)): a definite matrix (a
// 1d Laplacian plus a coupling to the next-but-one unknown), an indefinite one
// (the same with every third diagonal entry negative: LDL^T with pivoting), new
// values on the same pattern (the analysis kept), a solve with the
// factorisation of prepare(), and a singular matrix (one clear SolverFailure,
// no NaN).
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <restshape/base/input_error.h>
#include <restshape/base/mpi_start.h>
#include <restshape/solver/linear_solver.h>

#include <cmath>

#include "banded_matrix.h"
#include "checks.h"

using namespace dealii;
using namespace RestShape;
using checks::expect;

namespace
{
  constexpr unsigned int n = 400;

  /// The matrix: diagonal @p diagonal(i), -1 to the neighbours, 0.25 to
  /// the next-but-one unknowns (symmetric).
  template <typename Diagonal>
  void
  fill(MatrixType &A, const Diagonal &diagonal)
  {
    A = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        A.set(i, i, diagonal(i));
        if (i + 1 < n)
          {
            A.set(i, i + 1, -1.);
            A.set(i + 1, i, -1.);
          }
        if (i + 2 < n)
          {
            A.set(i, i + 2, 0.25);
            A.set(i + 2, i, 0.25);
          }
      }
    A.compress(VectorOperation::insert);
  }

  /// |x - x_true| / |x_true| after solving A x = A x_true.
  double
  error(LinearSolver &solver, const MatrixType &A, const VectorType &x_true)
  {
    VectorType b(x_true), x(x_true);
    A.vmult(b, x_true);
    x = 0;
    solver.solve(A, x, b);
    x -= x_true;
    return x.l2_norm() / x_true.l2_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const IndexSet                   all = complete_index_set(n);
  MatrixType                       A;
  checks::reinit_banded(A, n, 2);
  VectorType x_true(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < n; ++i)
    x_true[i] = std::sin(0.1 * i) + 0.01 * i;
  x_true.compress(VectorOperation::insert);

  SolverParameters parameters{};
  parameters.linear_solver           = LinearSolverType::direct;
  parameters.symmetric_factorisation = true;
  LinearSolver ldlt(parameters, 1), lu(parameters, 1);
  lu.set_symmetric(false);

  fill(A, [](unsigned int) { return 2.6; });
  const double definite = error(ldlt, A, x_true);
  expect(definite < 1e-12, "definite: LDL^T error " + std::to_string(definite));
  const double definite_lu = error(lu, A, x_true);
  expect(definite_lu < 1e-12,
         "definite: LU error " + std::to_string(definite_lu));

  // New values on the same pattern: the kept analysis, a new factorisation.
  fill(A, [](unsigned int i) { return i % 3 == 0 ? -2.1 : 2.6; });
  const double indefinite = error(ldlt, A, x_true);
  expect(indefinite < 1e-10,
         "indefinite, same pattern: LDL^T error " + std::to_string(indefinite));
  const double indefinite_lu = error(lu, A, x_true);
  expect(indefinite_lu < 1e-10,
         "indefinite: LU error " + std::to_string(indefinite_lu));

  // prepare() and solve_prepared() with the same factorisation.
  VectorType b(x_true), x(x_true);
  A.vmult(b, x_true);
  ldlt.prepare(A);
  x = 0;
  ldlt.solve_prepared(x, b);
  x -= x_true;
  expect(x.l2_norm() / x_true.l2_norm() < 1e-10, "prepared: LDL^T solve");

  // A singular matrix: a clear failure, not NaN.
  A = 0;
  std::string message;
  try
    {
      error(ldlt, A, x_true);
    }
  catch (const SolverFailure &e)
    {
      message = e.what();
    }
  expect(message.find("could not factorise") != std::string::npos,
         "singular: " + message);
  return checks::failures == 0 ? 0 : 1;
}
