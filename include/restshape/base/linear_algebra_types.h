// The vector and matrix types of RestShape's solves: Trilinos's distributed
// vectors and sparse matrices (the Newton systems, the inverse's vectors),
// and deal.II's own distributed vector for the assembly's local copies.
#ifndef restshape_base_linear_algebra_types_h
#define restshape_base_linear_algebra_types_h

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace RestShape
{
  using VectorType = dealii::TrilinosWrappers::MPI::Vector;
  using MatrixType = dealii::TrilinosWrappers::SparseMatrix;
  /// The assembly's copy of a state vector (locally relevant entries).
  using BufferType = dealii::LinearAlgebra::distributed::Vector<double>;
} // namespace RestShape

#endif
