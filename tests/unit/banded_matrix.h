// What the unit tests of the linear solvers share: a square matrix with a
// band of nonzeros on one process.
#ifndef restshape_tests_unit_banded_matrix_h
#define restshape_tests_unit_banded_matrix_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <restshape/solver/linear_solver.h>

#include <algorithm>

namespace checks
{
  /// Initialise @p A as n x n with entries (i, j) for |i - j| <= @p band
  /// (all zero).
  inline void
  reinit_banded(RestShape::MatrixType &A,
                const unsigned int     n,
                const unsigned int     band)
  {
    const dealii::IndexSet         all = dealii::complete_index_set(n);
    dealii::DynamicSparsityPattern pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i < band ? 0 : i - band);
           j < std::min(n, i + band + 1);
           ++j)
        pattern.add(i, j);
    A.reinit(all, all, pattern, MPI_COMM_WORLD);
  }
} // namespace checks

#endif
