#include <Epetra_CrsMatrix.h>
#include <restshape/base/compressed_row.h>
#include <restshape/base/outer_product.h>

#include <algorithm>
#include <utility>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Row @p i of factor g g^T through Epetra's map lookup and search per
    /// entry: where the matrix's compressed rows are not at hand.
    void
    add_row(const double                                factor,
            const unsigned int                          i,
            const std::vector<types::global_dof_index> &dofs,
            const std::vector<double>                  &g,
            TrilinosWrappers::SparseMatrix             &tangent)
    {
      const unsigned int  n = dofs.size();
      std::vector<double> row(n);
      for (unsigned int j = 0; j < n; ++j)
        row[j] = factor * g[i] * g[j];
      tangent.add(dofs[i], n, dofs.data(), row.data(), false, false);
    }

    /// Whether the local rows @p r and @p other (>= 0) have the same
    /// columns.
    bool
    same_columns(const int *offsets, const int *indices, int r, int other)
    {
      return offsets[r + 1] - offsets[r] ==
               offsets[other + 1] - offsets[other] &&
             std::equal(indices + offsets[r],
                        indices + offsets[r + 1],
                        indices + offsets[other]);
    }
  } // namespace

  void
  add_outer_product(const double                                factor,
                    const std::vector<types::global_dof_index> &dofs,
                    const std::vector<double>                  &g,
                    TrilinosWrappers::SparseMatrix             &tangent)
  {
    // DoFs none of which is constrained: their rows straight into the
    // matrix (AffineConstraints' general path, which sorts the DoFs and
    // looks each one up in its constraints, took 70 % of
    // NodalVolumes::add_stiffness on the brain). Where the matrix's compressed
    // rows are at hand (this process's rows), each row's entries are found by
    // one walk along the row with the columns sorted (find_in_row), not by
    // Epetra's map lookup and search per entry (0.73e9 of the 1.08e9
    // instructions of add_stiffness on the in vivo brain); the values
    // added are the same.
    const unsigned int n      = dofs.size();
    Epetra_CrsMatrix  &matrix = const_cast<Epetra_CrsMatrix &>(
      static_cast<const TrilinosWrappers::SparseMatrix &>(tangent)
        .trilinos_matrix());
    int    *offsets = nullptr, *indices = nullptr;
    double *values = nullptr;
    std::vector<std::pair<int, unsigned int>> columns(n); // (local, j)
    bool direct = matrix.Filled() && matrix.StorageOptimized() &&
                  matrix.ExtractCrsDataPointers(offsets, indices, values) == 0;
    for (unsigned int j = 0; direct && j < n; ++j)
      {
        columns[j] = {matrix.LCID(static_cast<int>(dofs[j])), j};
        direct     = columns[j].first >= 0;
      }
    if (!direct)
      {
        for (unsigned int i = 0; i < n; ++i)
          add_row(factor, i, dofs, g, tangent);
        return;
      }
    // g in the columns' sorted order, each column then numbered by its
    // place in that order.
    std::sort(columns.begin(), columns.end());
    std::vector<double> g_sorted(n);
    for (unsigned int c = 0; c < n; ++c)
      {
        g_sorted[c]       = g[columns[c].second];
        columns[c].second = c;
      }
    std::vector<int> place(n);
    // The row whose columns place holds: a vertex's three rows have the
    // same columns, found once (find_in_row was 40 % of this function
    // on the in vivo brain).
    int found = -1;
    for (unsigned int i = 0; i < n; ++i)
      {
        const int r = matrix.LRID(static_cast<int>(dofs[i]));
        if (r < 0 || found < 0 || !same_columns(offsets, indices, r, found))
          {
            found = -1;
            if (r < 0 || !find_in_row(columns.data(),
                                      n,
                                      indices + offsets[r],
                                      indices + offsets[r + 1],
                                      place.data()))
              {
                add_row(factor, i, dofs, g, tangent);
                continue;
              }
            found = r;
          }
        const double gi            = factor * g[i];
        double      *values_of_row = values + offsets[r];
        for (unsigned int c = 0; c < n; ++c)
          values_of_row[place[c]] += gi * g_sorted[c];
      }
  }
} // namespace RestShape
