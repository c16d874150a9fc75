// Adds cell matrices and right-hand sides into the Newton system. A cell
// none of whose DoFs is constrained, and all of whose rows this process
// owns, goes straight into the value arrays of the Trilinos matrix, at
// positions found once per cell and sparsity (a cached index: the row's
// start and each entry's place in the row). Epetra's own path looks each
// entry up in a map and by a binary search on every assembly (40 % of a
// P1 matrix assembly, profile of prm/brain.prm). Every other cell goes
// through AffineConstraints::distribute_local_to_global. Both add the same
// numbers in the same order. The index takes 2 bytes per cell-matrix
// entry: about half the matrix's own memory for P1, a sixth for P2.
#ifndef restshape_forward_tangent_scatter_h
#define restshape_forward_tangent_scatter_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cstdint>
#include <vector>

namespace RestShape
{
  class TangentScatter
  {
  public:
    /// The matrix was re-initialised: every cell's positions are stale.
    void
    forget();

    /// matrix += cell_matrix and rhs += cell_rhs at @p dofs, under
    /// @p constraints, for the cell of active index @p cell.
    void
    add(const unsigned int                                  cell,
        const dealii::AffineConstraints<double>            &constraints,
        const dealii::FullMatrix<double>                   &cell_matrix,
        const dealii::Vector<double>                       &cell_rhs,
        const std::vector<dealii::types::global_dof_index> &dofs,
        dealii::TrilinosWrappers::SparseMatrix             &matrix,
        dealii::LinearAlgebra::distributed::Vector<double> &rhs);

  private:
    enum class Route : std::uint8_t
    {
      unknown,
      direct,  // positions cached
      indirect // through AffineConstraints (rows of other processes)
    };

    /// The cell's route, its positions found if not known yet.
    Route
    route(const unsigned int                                  cell,
          const std::vector<dealii::types::global_dof_index> &dofs,
          const Epetra_CrsMatrix                             &matrix);

    /// Find the positions of a cell's entries; false where there are none.
    bool
    locate(const unsigned int                                  cell,
           const std::vector<dealii::types::global_dof_index> &dofs,
           const Epetra_CrsMatrix                             &matrix);

    unsigned int n = 0; // DoFs per cell
    // The matrix the positions are for: its value array and size.
    const double              *values   = nullptr;
    int                        nonzeros = 0;
    std::vector<Route>         routes;    // per cell
    std::vector<int>           row_start; // n per cell: offset of row i
    std::vector<std::uint16_t> position;  // n * n per cell: (i, j) in row i
  };
} // namespace RestShape

#endif
