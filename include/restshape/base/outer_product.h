// A dense symmetric outer product added into a Trilinos matrix: the
// stiffness factor g g^T of a volume (a vertex's averaged nodal pressure,
// a pressure unknown of the mixed formulation) over the DoFs it depends on.
#ifndef restshape_base_outer_product_h
#define restshape_base_outer_product_h

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace RestShape
{
  /// tangent += @p factor g g^T at the rows and columns @p dofs (distinct,
  /// none of them constrained, every pair in the sparsity pattern).
  void
  add_outer_product(const double                                        factor,
                    const std::vector<dealii::types::global_dof_index> &dofs,
                    const std::vector<double>                          &g,
                    dealii::TrilinosWrappers::SparseMatrix &tangent);
} // namespace RestShape

#endif
