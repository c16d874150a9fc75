#include <Epetra_CrsMatrix.h>
#include <restshape/base/compressed_row.h>
#include <restshape/fem/element_limits.h>
#include <restshape/fem/tangent_scatter.h>

#include <algorithm>
#include <array>
#include <cmath>
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
    // On the stack: this runs once per cell, and allocations were a fifth
    // of it. A larger cell takes AffineConstraints's path.
    if (n > max_dofs_per_cell)
      return false;
    std::array<std::pair<int, unsigned int>, max_dofs_per_cell> columns;
    for (unsigned int j = 0; j < n; ++j)
      {
        columns[j] = {matrix.LCID(static_cast<int>(dofs[j])), j};
        if (columns[j].first < 0)
          return false;
      }
    std::sort(columns.begin(), columns.begin() + n);
    // The rows straight from the compressed storage (route() has checked
    // that the matrix has it): ExtractMyRowView checks its arguments on
    // each call.
    int    *offsets = nullptr, *all_indices = nullptr;
    double *unused = nullptr;
    if (matrix.ExtractCrsDataPointers(offsets, all_indices, unused) != 0)
      return false;
    std::array<std::pair<int, const int *>, max_dofs_per_cell> rows;
    for (unsigned int i = 0; i < n; ++i)
      {
        const int row = matrix.LRID(static_cast<int>(dofs[i]));
        if (row < 0)
          return false;
        const int        length  = offsets[row + 1] - offsets[row];
        const int *const indices = all_indices + offsets[row];
        if (length > std::numeric_limits<std::uint16_t>::max())
          return false;
        row_start[cell * n + i] = offsets[row];
        rows[i]                 = {length, indices};
        std::uint16_t *place    = &position[(cell * n + i) * n];
        // Another component of a node seen before: the same columns.
        const auto same =
          std::find_if(rows.begin(), rows.begin() + i, [&](const auto &other) {
            return other.first == length &&
                   std::equal(indices, indices + length, other.second);
          });
        if (same != rows.begin() + i)
          {
            const std::uint16_t *known =
              &position[(cell * n + (same - rows.begin())) * n];
            std::copy(known, known + n, place);
            continue;
          }
        // Not found: not in the sparsity (deal.II's path says so), or the
        // row's columns are not sorted (deal.II's path adds it).
        if (!find_in_row(columns.data(), n, indices, indices + length, place))
          return false;
      }
    return true;
  }

  void
  TangentScatter::add(const unsigned int                          cell,
                      const ConstraintLookup                     &lookup,
                      const std::vector<unsigned int>            &local,
                      const FullMatrix<double>                   &cell_matrix,
                      const Vector<double>                       &cell_rhs,
                      const std::vector<types::global_dof_index> &dofs,
                      TrilinosWrappers::SparseMatrix             &matrix,
                      LinearAlgebra::distributed::Vector<double> &rhs)
  {
    const ConstraintLookup::Kind kind = lookup.strongest(local);
    if (kind == ConstraintLookup::Kind::linked ||
        route(cell, dofs, matrix.trilinos_matrix()) != Route::direct)
      {
        lookup.constraints().distribute_local_to_global(
          cell_matrix, cell_rhs, dofs, matrix, rhs);
        return;
      }
    double *const all_values = matrix.trilinos_matrix()[0];
    if (kind == ConstraintLookup::Kind::fixed)
      {
        add_with_fixed(
          cell, lookup, local, cell_matrix, cell_rhs, all_values, rhs);
        return;
      }
    for (unsigned int i = 0; i < n; ++i)
      {
        double              *row   = all_values + row_start[cell * n + i];
        const std::uint16_t *place = &position[(cell * n + i) * n];
        // Through a raw pointer: FullMatrix's operator() reloads the
        // table's size and data on each entry.
        const double *const from = &cell_matrix(i, 0);
        for (unsigned int j = 0; j < n; ++j)
          row[place[j]] += from[j];
        rhs.local_element(local[i]) += cell_rhs(i);
      }
  }

  void
  TangentScatter::add_with_fixed(
    const unsigned int                          cell,
    const ConstraintLookup                     &lookup,
    const std::vector<unsigned int>            &local,
    const FullMatrix<double>                   &cell_matrix,
    const Vector<double>                       &cell_rhs,
    double *const                               all_values,
    LinearAlgebra::distributed::Vector<double> &rhs)
  {
    using Kind = ConstraintLookup::Kind;
    fixed.clear();
    inhomogeneous.clear();
    // The inhomogeneous ones last to first, AffineConstraints's order.
    for (unsigned int k = n; k-- > 0;)
      if (lookup.kind(local[k]) == Kind::fixed)
        {
          fixed.push_back(k);
          if (lookup.inhomogeneity(local[k]) != 0.)
            inhomogeneous.push_back(k);
        }
    for (unsigned int i = 0; i < n; ++i)
      {
        if (lookup.kind(local[i]) == Kind::fixed)
          continue;
        double              *row   = all_values + row_start[cell * n + i];
        const std::uint16_t *place = &position[(cell * n + i) * n];
        for (unsigned int j = 0; j < n; ++j)
          if (lookup.kind(local[j]) == Kind::free)
            row[place[j]] += cell_matrix(i, j);
        // The fixed values' columns moved to the right-hand side.
        double value = cell_rhs(i);
        for (const unsigned int k : inhomogeneous)
          value -= cell_matrix(i, k) * lookup.inhomogeneity(local[k]);
        if (value != 0.)
          rhs.local_element(local[i]) += value;
      }
    // The fixed rows: their diagonal only, of the cell's scale.
    double mean_diagonal = 0;
    for (unsigned int i = 0; i < n; ++i)
      mean_diagonal += std::abs(cell_matrix(i, i));
    mean_diagonal /= n;
    if (mean_diagonal == 0.)
      mean_diagonal = cell_matrix.l1_norm() / n;
    if (mean_diagonal == 0.)
      mean_diagonal = 1.;
    for (const unsigned int k : fixed)
      {
        const double diagonal = std::abs(cell_matrix(k, k));
        all_values[row_start[cell * n + k] +
                   position[(cell * n + k) * n + k]] +=
          diagonal != 0. ? diagonal : mean_diagonal;
      }
  }
} // namespace RestShape
