#include <Epetra_CrsMatrix.h>
#include <restshape/forward/tangent_scatter.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace RestShape
{
  using namespace dealii;

  void
  TangentScatter::forget()
  {
    routes.clear();
    row_start.clear();
    position.clear();
    values   = nullptr;
    nonzeros = 0;
  }

  TangentScatter::Route
  TangentScatter::route(const unsigned int                          cell,
                        const std::vector<types::global_dof_index> &dofs,
                        const Epetra_CrsMatrix                     &matrix)
  {
    // Positions are offsets into one contiguous value array.
    if (!matrix.Filled() || !matrix.StorageOptimized() ||
        matrix.NumMyRows() == 0)
      return Route::indirect;
    if (matrix[0] != values || matrix.NumMyNonzeros() != nonzeros ||
        dofs.size() != n)
      {
        forget();
        values   = matrix[0];
        nonzeros = matrix.NumMyNonzeros();
        n        = dofs.size();
      }
    if (cell >= routes.size())
      {
        routes.resize(cell + 1, Route::unknown);
        row_start.resize(routes.size() * n);
        position.resize(routes.size() * n * n);
      }
    if (routes[cell] == Route::unknown)
      routes[cell] =
        locate(cell, dofs, matrix) ? Route::direct : Route::indirect;
    return routes[cell];
  }

  bool
  TangentScatter::locate(const unsigned int                          cell,
                         const std::vector<types::global_dof_index> &dofs,
                         const Epetra_CrsMatrix                     &matrix)
  {
    std::vector<std::pair<int, unsigned int>> columns(n); // (column, j)
    for (unsigned int j = 0; j < n; ++j)
      {
        columns[j] = {matrix.LCID(static_cast<int>(dofs[j])), j};
        if (columns[j].first < 0)
          return false;
      }
    std::sort(columns.begin(), columns.end());
    for (unsigned int i = 0; i < n; ++i)
      {
        const int row        = matrix.LRID(static_cast<int>(dofs[i]));
        int       length     = 0;
        int      *indices    = nullptr;
        double   *row_values = nullptr;
        if (row < 0 ||
            matrix.ExtractMyRowView(row, length, row_values, indices) != 0 ||
            length > std::numeric_limits<std::uint16_t>::max())
          return false;
        row_start[cell * n + i] = row_values - values;
        int k                   = 0;
        for (const auto &[col, j] : columns)
          {
            while (k < length && indices[k] < col)
              ++k;
            // Not found: not in the sparsity (deal.II's path says so), or
            // the row's columns are not sorted (deal.II's path adds it).
            if (k == length || indices[k] != col)
              return false;
            position[(cell * n + i) * n + j] = k;
          }
      }
    return true;
  }

  void
  TangentScatter::add(const unsigned int                          cell,
                      const AffineConstraints<double>            &constraints,
                      const FullMatrix<double>                   &cell_matrix,
                      const Vector<double>                       &cell_rhs,
                      const std::vector<types::global_dof_index> &dofs,
                      TrilinosWrappers::SparseMatrix             &matrix,
                      LinearAlgebra::distributed::Vector<double> &rhs)
  {
    const bool constrained =
      std::any_of(dofs.begin(), dofs.end(), [&](const auto dof) {
        return constraints.is_constrained(dof);
      });
    if (constrained ||
        route(cell, dofs, matrix.trilinos_matrix()) != Route::direct)
      {
        constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, dofs, matrix, rhs);
        return;
      }
    double *const all_values = matrix.trilinos_matrix()[0];
    for (unsigned int i = 0; i < n; ++i)
      {
        double              *row   = all_values + row_start[cell * n + i];
        const std::uint16_t *place = &position[(cell * n + i) * n];
        for (unsigned int j = 0; j < n; ++j)
          row[place[j]] += cell_matrix(i, j);
        rhs(dofs[i]) += cell_rhs(i);
      }
  }
} // namespace RestShape
