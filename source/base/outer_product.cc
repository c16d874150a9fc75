#include <Epetra_CrsMatrix.h>
#include <restshape/base/compressed_row.h>
#include <restshape/base/outer_product.h>

#include <algorithm>
#include <utility>

namespace RestShape
{
  using namespace dealii;

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
    if (direct)
      std::sort(columns.begin(), columns.end());
    std::vector<int>    place(n);
    std::vector<double> row(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const int r = direct ? matrix.LRID(static_cast<int>(dofs[i])) : -1;
        if (r >= 0 && find_in_row(columns.data(),
                                  n,
                                  indices + offsets[r],
                                  indices + offsets[r + 1],
                                  place.data()))
          {
            for (unsigned int j = 0; j < n; ++j)
              values[offsets[r] + place[j]] += factor * g[i] * g[j];
            continue;
          }
        for (unsigned int j = 0; j < n; ++j)
          row[j] = factor * g[i] * g[j];
        tangent.add(dofs[i], n, dofs.data(), row.data(), false, false);
      }
  }
} // namespace RestShape
