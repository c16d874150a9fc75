// SymmetricMumps: MUMPS's LDL^T factorisation of a symmetric matrix, called
// directly (Amesos passes MUMPS every matrix as unsymmetric).
#ifndef restshape_solver_symmetric_mumps_h
#define restshape_solver_symmetric_mumps_h

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>

#include <vector>

namespace RestShape
{
  /**
   * The sparse direct solver MUMPS in its symmetric mode (SYM = 2: LDL^T
   * with two-by-two pivots, for definite and indefinite matrices), on one
   * process. It is given the lower triangle only: its factors take about
   * half the memory and its factorisation about half the flops of the LU
   * factorisation that Amesos_Mumps asks MUMPS for (Amesos sets SYM = 0
   * whatever the matrix's MatrixProperty says, Trilinos issues 2331 and
   * 2332). The analysis (the ordering) is done once per sparsity pattern;
   * each factorise() copies the current values.
   */
  class SymmetricMumps
  {
  public:
    SymmetricMumps();
    ~SymmetricMumps();
    SymmetricMumps(const SymmetricMumps &) = delete;
    SymmetricMumps &
    operator=(const SymmetricMumps &) = delete;

    /// Analyse (if the pattern is new) and factorise @p A, a matrix on one
    /// process whose upper triangle mirrors its lower one. Returns MUMPS's
    /// INFOG(1): 0 on success, negative on failure.
    int
    factorise(const Epetra_CrsMatrix &A);
    /// Solve with the last factorisation: @p x holds the right-hand side
    /// on entry, the solution on return. Returns INFOG(1).
    int
    solve(double *x);
    /// MUMPS's INFOG(1) and INFOG(2) of the last call, for messages.
    int
    error() const;
    int
    error_detail() const;

  private:
    /// The lower triangle of @p A in MUMPS's form (1-based indices):
    /// pattern and values, or (@p with_pattern false) the values only, in
    /// the order of the pattern copied before.
    void
    copy_lower_triangle(const Epetra_CrsMatrix &A, const bool with_pattern);
    void
    call(const int job);

    DMUMPS_STRUC_C         id;
    bool                   analysed        = false;
    int                    pattern_entries = 0; // of the analysed matrix
    std::vector<MUMPS_INT> rows, columns;
    std::vector<double>    values;
  };
} // namespace RestShape

#endif
