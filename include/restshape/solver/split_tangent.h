// The tangent of the averaged nodal pressure (mixed linear tetrahedra) as
// the cells' narrow matrix plus one rank-one term per vertex: W = N +
// sum_n k_n g_n g_n^T + E. Each term couples every DoF of the cells
// around its vertex, which makes the assembled matrix W's rows about 3.5
// times as long as N's; the split applies W at the cost of N and the
// terms' two passes over their DoFs, for CG and for ML's smoothers and
// residuals on the finest level. ML builds its hierarchy from W's rows,
// which this class hands on (Epetra_RowMatrix).
#ifndef restshape_solver_split_tangent_h
#define restshape_solver_split_tangent_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Epetra_Export.h>
#include <Epetra_RowMatrix.h>
#include <Epetra_Vector.h>
#include <restshape/base/linear_algebra_types.h>

#include <memory>
#include <vector>

namespace RestShape
{
  class SplitTangent : public virtual Epetra_RowMatrix
  {
  public:
    /// N's rows: @p narrow (locally relevant rows, distributed) over the
    /// locally owned DoFs @p owned. Forgets the terms.
    void
    reinit(const dealii::IndexSet               &owned,
           const dealii::DynamicSparsityPattern &narrow,
           const MPI_Comm                        communicator);

    /// N, for the cells' matrices; zeroed by clear().
    MatrixType &
    narrow()
    {
      return narrow_matrix;
    }

    /// Before an assembly: N = 0, no terms.
    void
    clear();

    /// The term @p factor g g^T over the DoFs @p dofs, as
    /// AffineConstraints::distribute_local_to_global puts it into W under
    /// @p constraints (homogeneous): g projected, C^T g.
    void
    add_term(const double                                        factor,
             const std::vector<dealii::types::global_dof_index> &dofs,
             const std::vector<double>                          &g,
             const dealii::AffineConstraints<double>            &constraints);

    /**
     * After the assembly, with W holding everything but N (its terms
     * added, compressed): W += N; the terms' DoFs as W's local columns.
     * If a term's DoF is not among them, the split is not valid and
     * applies() says no for W.
     */
    void
    finish(MatrixType &wide);

    /// Whether the split applies @p wide (the matrix of the last finish()).
    bool
    applies(const MatrixType &wide) const
    {
      return valid && &wide.trilinos_matrix() == wide_matrix;
    }

    /// E = diag(W) - diag(N + terms): W's diagonal as it is now (the
    /// constrained rows', a Newton step's shift). Before each solve.
    void
    refresh_diagonal();

    /// dst = W src.
    void
    vmult(VectorType &dst, const VectorType &src) const;

    // --- Epetra_RowMatrix: W's rows; its product the split's -----------
    int
    NumMyRowEntries(int row, int &n) const override;
    int
    MaxNumEntries() const override;
    int
    ExtractMyRowCopy(int row, int length, int &n, double *values, int *indices)
      const override;
    int
    ExtractDiagonalCopy(Epetra_Vector &diagonal) const override;
    int
    Multiply(bool                      transpose,
             const Epetra_MultiVector &X,
             Epetra_MultiVector       &Y) const override;
    int
    Solve(bool, bool, bool, const Epetra_MultiVector &, Epetra_MultiVector &)
      const override
    {
      return -1;
    }
    int
    InvRowSums(Epetra_Vector &x) const override;
    int
    LeftScale(const Epetra_Vector &) override
    {
      return -1;
    }
    int
    InvColSums(Epetra_Vector &x) const override;
    int
    RightScale(const Epetra_Vector &) override
    {
      return -1;
    }
    bool
    Filled() const override
    {
      return true;
    }
    double
    NormInf() const override;
    double
    NormOne() const override;
    int
    NumGlobalNonzeros() const override;
    long long
    NumGlobalNonzeros64() const override;
    int
    NumGlobalRows() const override;
    long long
    NumGlobalRows64() const override;
    int
    NumGlobalCols() const override;
    long long
    NumGlobalCols64() const override;
    int
    NumGlobalDiagonals() const override;
    long long
    NumGlobalDiagonals64() const override;
    int
    NumMyNonzeros() const override;
    int
    NumMyRows() const override;
    int
    NumMyCols() const override;
    int
    NumMyDiagonals() const override;
    bool
    LowerTriangular() const override;
    bool
    UpperTriangular() const override;
    const Epetra_Map &
    RowMatrixRowMap() const override;
    const Epetra_Map &
    RowMatrixColMap() const override;
    const Epetra_Import *
    RowMatrixImporter() const override;
    int
    SetUseTranspose(bool use) override
    {
      return use ? -1 : 0;
    }
    int
    Apply(const Epetra_MultiVector &X, Epetra_MultiVector &Y) const override
    {
      return Multiply(false, X, Y);
    }
    int
    ApplyInverse(const Epetra_MultiVector &,
                 Epetra_MultiVector &) const override
    {
      return -1;
    }
    const char *
    Label() const override
    {
      return "RestShape::SplitTangent";
    }
    bool
    UseTranspose() const override
    {
      return false;
    }
    bool
    HasNormInf() const override
    {
      return true;
    }
    const Epetra_Comm &
    Comm() const override;
    const Epetra_Map &
    OperatorDomainMap() const override;
    const Epetra_Map &
    OperatorRangeMap() const override;
    const Epetra_BlockMap &
    Map() const override;

  private:
    /// W's Epetra matrix (finish()).
    const Epetra_CrsMatrix &
    wide() const;
    /// The places of N's entries and of the diagonals in W's and N's
    /// value arrays; false if the matrices are not stored in one array
    /// each or W lacks one of N's entries.
    bool
    locate(const Epetra_CrsMatrix &N, const Epetra_CrsMatrix &W);
    /// base_diagonal from N and the terms (of every process).
    void
    set_base_diagonal();
    /// Y += the terms' product with X, one column.
    void
    add_terms(const double *x, double *y) const;

    MatrixType narrow_matrix;
    // The terms: factor k_n, and in [start[n], start[n + 1]) their DoFs
    // (global until finish(), W's local columns after) and g values.
    std::vector<double>                          factors;
    std::vector<unsigned int>                    start = {0};
    std::vector<dealii::types::global_dof_index> dofs;
    std::vector<int>                             columns;
    std::vector<double>                          values;
    // diag(N + terms) at finish(), and E (refresh_diagonal()).
    std::vector<double> base_diagonal, extra;
    // The place in W's values of each of N's values, and of each row's
    // diagonal in N's and W's (-1: none); found once per pattern.
    std::vector<int>               position, narrow_diagonal, wide_diagonal;
    bool                           located     = false;
    const Epetra_CrsMatrix        *wide_matrix = nullptr;
    std::unique_ptr<Epetra_Export> exporter; // columns to rows
    // Multiply()'s work vectors: X and the terms' sums by W's columns,
    // those sums by its rows.
    mutable std::unique_ptr<Epetra_MultiVector> x_columns, y_columns, y_rows;
    bool                                        valid = false;
  };
} // namespace RestShape

#endif
