// Adds cell matrices and right-hand sides into the Newton system. A cell
// none of whose DoFs is linked to others by a constraint, and all of whose
// rows this process owns, goes straight into the value arrays of the
// Trilinos matrix, at positions found once per cell and sparsity (a cached
// index: the row's start and each entry's place in the row). Epetra's own
// path looks each entry up in a map and by a binary search on every
// assembly (40 % of a P1 matrix assembly, profile of prm/brain.prm). A
// fixed DoF's row and column are left out, its diagonal gets |K_ii| (the
// mean |K_jj| if that is zero) and the free rows' right-hand sides lose
// K_ik g_k of its value g_k, as AffineConstraints does. Every other cell
// goes through AffineConstraints::distribute_local_to_global. Both add the
// same numbers in the same order. The index takes 2 bytes per cell-matrix
// entry: about half the matrix's own memory for P1, a sixth for P2. Rows
// of a node's three components share their columns: their positions are
// found once.
#ifndef restshape_fem_tangent_scatter_h
#define restshape_fem_tangent_scatter_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <restshape/fem/constraint_lookup.h>

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

    /// matrix += cell_matrix and rhs += cell_rhs at @p dofs (local
    /// indices of rhs @p local), under the constraints of @p lookup, for
    /// the cell of active index @p cell.
    void
    add(const unsigned int                                  cell,
        const ConstraintLookup                             &lookup,
        const std::vector<unsigned int>                    &local,
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

    /// The cached cell of fixed DoFs: as AffineConstraints adds it.
    void
    add_with_fixed(const unsigned int                cell,
                   const ConstraintLookup           &lookup,
                   const std::vector<unsigned int>  &local,
                   const dealii::FullMatrix<double> &cell_matrix,
                   const dealii::Vector<double>     &cell_rhs,
                   double                           *all_values,
                   dealii::LinearAlgebra::distributed::Vector<double> &rhs);

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
    std::vector<unsigned int>  fixed, inhomogeneous; // a cell's local DoFs
  };
} // namespace RestShape

#endif
