#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <restshape/solver/split_tangent.h>

#include <algorithm>

namespace RestShape
{
  using namespace dealii;

  void
  SplitTangent::reinit(const IndexSet               &owned,
                       const DynamicSparsityPattern &narrow,
                       const MPI_Comm                communicator)
  {
    narrow_matrix.reinit(owned, owned, narrow, communicator);
    position.clear();
    located     = false;
    wide_matrix = nullptr;
    exporter.reset();
    x_columns.reset();
    y_columns.reset();
    y_rows.reset();
    clear();
  }

  void
  SplitTangent::clear()
  {
    narrow_matrix = 0;
    factors.clear();
    start = {0};
    dofs.clear();
    values.clear();
    valid = false;
  }

  void
  SplitTangent::add_term(const double                                factor,
                         const std::vector<types::global_dof_index> &patch,
                         const std::vector<double>                  &g,
                         const AffineConstraints<double> &constraints)
  {
    // The patch's free DoFs (distinct), then each constrained one's share
    // on the DoFs it is constrained to.
    for (unsigned int i = 0; i < patch.size(); ++i)
      if (!constraints.is_constrained(patch[i]))
        {
          dofs.push_back(patch[i]);
          values.push_back(g[i]);
        }
    for (unsigned int i = 0; i < patch.size(); ++i)
      if (const auto *entries = constraints.get_constraint_entries(patch[i]))
        for (const auto &[dof, weight] : *entries) // none: a fixed DoF
          {
            const auto at =
              std::find(dofs.begin() + start.back(), dofs.end(), dof);
            if (at == dofs.end())
              {
                dofs.push_back(dof);
                values.push_back(weight * g[i]);
              }
            else
              values[at - dofs.begin()] += weight * g[i];
          }
    factors.push_back(factor);
    start.push_back(dofs.size());
  }

  bool
  SplitTangent::locate(const Epetra_CrsMatrix &N, const Epetra_CrsMatrix &W)
  {
    position.clear();
    narrow_diagonal.assign(N.NumMyRows(), -1);
    wide_diagonal.assign(W.NumMyRows(), -1);
    int    *offsets_n = nullptr, *indices_n = nullptr;
    int    *offsets_w = nullptr, *indices_w = nullptr;
    double *values = nullptr;
    if (!N.StorageOptimized() || !W.StorageOptimized() ||
        const_cast<Epetra_CrsMatrix &>(N).ExtractCrsDataPointers(offsets_n,
                                                                 indices_n,
                                                                 values) != 0 ||
        const_cast<Epetra_CrsMatrix &>(W).ExtractCrsDataPointers(offsets_w,
                                                                 indices_w,
                                                                 values) != 0)
      return false;
    for (int r = 0; r < N.NumMyRows(); ++r)
      {
        const int *first = indices_w + offsets_w[r];
        const int *last  = indices_w + offsets_w[r + 1];
        const int  row   = N.GRID(r);
        for (int k = offsets_n[r]; k < offsets_n[r + 1]; ++k)
          {
            const int  global = N.GCID(indices_n[k]);
            const int *at     = std::find(first, last, W.LCID(global));
            if (at == last)
              return false;
            position.push_back(at - indices_w);
            if (global == row)
              narrow_diagonal[r] = k;
          }
        const int *diagonal = std::find(first, last, W.LCID(row));
        wide_diagonal[r]    = diagonal == last ? -1 : diagonal - indices_w;
      }
    return true;
  }

  void
  SplitTangent::finish(MatrixType &wide_wrapper)
  {
    narrow_matrix.compress(VectorOperation::add);
    Epetra_CrsMatrix &W = const_cast<Epetra_CrsMatrix &>(
      static_cast<const MatrixType &>(wide_wrapper).trilinos_matrix());
    Epetra_CrsMatrix &N =
      const_cast<Epetra_CrsMatrix &>(narrow_matrix.trilinos_matrix());
    if (wide_matrix != &W)
      {
        wide_matrix = &W;
        // On every process or on none: the products are collective.
        int mine = locate(N, W) ? 1 : 0, all = 0;
        W.Comm().MinAll(&mine, &all, 1);
        located  = (all == 1);
        exporter = std::make_unique<Epetra_Export>(W.ColMap(), W.RowMap());
        x_columns.reset();
        y_columns.reset();
        y_rows.reset();
      }
    if (!located)
      {
        // Without N's places in W (matrices not in one array each): W
        // gets N through deal.II, and the split does not apply.
        wide_wrapper.add(1., narrow_matrix);
        valid = false;
        return;
      }
    // W += N at N's places in W.
    int    *offsets = nullptr, *indices = nullptr;
    double *v_narrow = nullptr, *v_wide = nullptr;
    N.ExtractCrsDataPointers(offsets, indices, v_narrow);
    W.ExtractCrsDataPointers(offsets, indices, v_wide);
    for (std::size_t k = 0; k < position.size(); ++k)
      v_wide[position[k]] += v_narrow[k];
    columns.resize(dofs.size());
    valid = true;
    for (std::size_t j = 0; j < dofs.size(); ++j)
      {
        columns[j] = W.LCID(static_cast<int>(dofs[j]));
        valid      = valid && columns[j] >= 0;
      }
    // Valid only if valid on every process: Multiply is collective.
    int mine = valid ? 1 : 0, all = 0;
    W.Comm().MinAll(&mine, &all, 1);
    valid = (all == 1);
    if (valid)
      set_base_diagonal();
  }

  void
  SplitTangent::set_base_diagonal()
  {
    // diag(N + terms), by W's rows: the terms of other processes' vertices
    // too (exported).
    const Epetra_CrsMatrix &W = wide();
    Epetra_Vector           terms(W.ColMap()), diagonal(W.RowMap());
    for (std::size_t t = 0; t < factors.size(); ++t)
      for (unsigned int j = start[t]; j < start[t + 1]; ++j)
        terms[columns[j]] += factors[t] * values[j] * values[j];
    diagonal.Export(terms, *exporter, Add);
    const double *v_narrow = narrow_matrix.trilinos_matrix()[0];
    base_diagonal.resize(diagonal.MyLength());
    for (int i = 0; i < diagonal.MyLength(); ++i)
      base_diagonal[i] =
        diagonal[i] +
        (narrow_diagonal[i] < 0 ? 0. : v_narrow[narrow_diagonal[i]]);
    refresh_diagonal();
  }

  void
  SplitTangent::refresh_diagonal()
  {
    if (!valid)
      return;
    const double *v_wide = (*wide_matrix)[0];
    extra.resize(base_diagonal.size());
    for (std::size_t i = 0; i < extra.size(); ++i)
      extra[i] = (wide_diagonal[i] < 0 ? 0. : v_wide[wide_diagonal[i]]) -
                 base_diagonal[i];
  }

  void
  SplitTangent::add_terms(const double *x, double *y) const
  {
    for (std::size_t t = 0; t < factors.size(); ++t)
      {
        const unsigned int end = start[t + 1];
        double             s   = 0;
        for (unsigned int j = start[t]; j < end; ++j)
          s += values[j] * x[columns[j]];
        s *= factors[t];
        for (unsigned int j = start[t]; j < end; ++j)
          y[columns[j]] += s * values[j];
      }
  }

  int
  SplitTangent::Multiply(const bool                transpose,
                         const Epetra_MultiVector &X,
                         Epetra_MultiVector       &Y) const
  {
    // W is symmetric: W^T = W.
    (void)transpose;
    const Epetra_CrsMatrix &W = wide();
    if (!valid) // an AMG kept from an earlier assembly
      return W.Multiply(false, X, Y);
    if (const int error = narrow_matrix.trilinos_matrix().Multiply(false, X, Y))
      return error;
    const int n = X.NumVectors();
    if (x_columns == nullptr || x_columns->NumVectors() != n)
      {
        x_columns = std::make_unique<Epetra_MultiVector>(W.ColMap(), n);
        y_columns = std::make_unique<Epetra_MultiVector>(W.ColMap(), n);
        y_rows    = std::make_unique<Epetra_MultiVector>(W.RowMap(), n);
      }
    if (W.Importer() != nullptr)
      x_columns->Import(X, *W.Importer(), Insert);
    else
      *x_columns = X;
    y_columns->PutScalar(0.);
    for (int v = 0; v < n; ++v)
      add_terms((*x_columns)[v], (*y_columns)[v]);
    Epetra_MultiVector &rows = *y_rows; // own and remote sums
    rows.PutScalar(0.);
    rows.Export(*y_columns, *exporter, Add);
    for (int v = 0; v < n; ++v)
      for (int i = 0; i < Y.MyLength(); ++i)
        Y[v][i] += rows[v][i] + extra[i] * X[v][i];
    return 0;
  }

  void
  SplitTangent::vmult(VectorType &dst, const VectorType &src) const
  {
    Multiply(false, src.trilinos_vector(), dst.trilinos_vector());
  }

  const Epetra_CrsMatrix &
  SplitTangent::wide() const
  {
    return *wide_matrix;
  }

  // --- W's rows and maps ----------------------------------------------

  int
  SplitTangent::NumMyRowEntries(int row, int &n) const
  {
    return wide().NumMyRowEntries(row, n);
  }
  int
  SplitTangent::MaxNumEntries() const
  {
    return wide().MaxNumEntries();
  }
  int
  SplitTangent::ExtractMyRowCopy(int     row,
                                 int     length,
                                 int    &n,
                                 double *v,
                                 int    *indices) const
  {
    return wide().ExtractMyRowCopy(row, length, n, v, indices);
  }
  int
  SplitTangent::ExtractDiagonalCopy(Epetra_Vector &diagonal) const
  {
    return wide().ExtractDiagonalCopy(diagonal);
  }
  int
  SplitTangent::InvRowSums(Epetra_Vector &x) const
  {
    return wide().InvRowSums(x);
  }
  int
  SplitTangent::InvColSums(Epetra_Vector &x) const
  {
    return wide().InvColSums(x);
  }
  double
  SplitTangent::NormInf() const
  {
    return wide().NormInf();
  }
  double
  SplitTangent::NormOne() const
  {
    return wide().NormOne();
  }
  int
  SplitTangent::NumGlobalNonzeros() const
  {
    return wide().NumGlobalNonzeros();
  }
  long long
  SplitTangent::NumGlobalNonzeros64() const
  {
    return wide().NumGlobalNonzeros64();
  }
  int
  SplitTangent::NumGlobalRows() const
  {
    return wide().NumGlobalRows();
  }
  long long
  SplitTangent::NumGlobalRows64() const
  {
    return wide().NumGlobalRows64();
  }
  int
  SplitTangent::NumGlobalCols() const
  {
    return wide().NumGlobalCols();
  }
  long long
  SplitTangent::NumGlobalCols64() const
  {
    return wide().NumGlobalCols64();
  }
  int
  SplitTangent::NumGlobalDiagonals() const
  {
    return wide().NumGlobalDiagonals();
  }
  long long
  SplitTangent::NumGlobalDiagonals64() const
  {
    return wide().NumGlobalDiagonals64();
  }
  int
  SplitTangent::NumMyNonzeros() const
  {
    return wide().NumMyNonzeros();
  }
  int
  SplitTangent::NumMyRows() const
  {
    return wide().NumMyRows();
  }
  int
  SplitTangent::NumMyCols() const
  {
    return wide().NumMyCols();
  }
  int
  SplitTangent::NumMyDiagonals() const
  {
    return wide().NumMyDiagonals();
  }
  bool
  SplitTangent::LowerTriangular() const
  {
    return wide().LowerTriangular();
  }
  bool
  SplitTangent::UpperTriangular() const
  {
    return wide().UpperTriangular();
  }
  const Epetra_Map &
  SplitTangent::RowMatrixRowMap() const
  {
    return wide().RowMatrixRowMap();
  }
  const Epetra_Map &
  SplitTangent::RowMatrixColMap() const
  {
    return wide().RowMatrixColMap();
  }
  const Epetra_Import *
  SplitTangent::RowMatrixImporter() const
  {
    return wide().RowMatrixImporter();
  }
  const Epetra_Comm &
  SplitTangent::Comm() const
  {
    return wide().Comm();
  }
  const Epetra_Map &
  SplitTangent::OperatorDomainMap() const
  {
    return wide().OperatorDomainMap();
  }
  const Epetra_Map &
  SplitTangent::OperatorRangeMap() const
  {
    return wide().OperatorRangeMap();
  }
  const Epetra_BlockMap &
  SplitTangent::Map() const
  {
    return wide().Map();
  }
} // namespace RestShape
