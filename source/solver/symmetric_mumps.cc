#include <mpi.h>
#include <restshape/solver/symmetric_mumps.h>

namespace RestShape
{
  namespace
  {
    // MUMPS's job codes and the control parameters set here (ICNTL(i) is
    // icntl[i - 1]).
    constexpr int job_init      = -1;
    constexpr int job_end       = -2;
    constexpr int job_analyse   = 1;
    constexpr int job_factorise = 2;
    constexpr int job_solve     = 3;
    /// SYM = 2: general symmetric (LDL^T with pivoting).
    constexpr int symmetric_indefinite = 2;
    /// ICNTL(7) = 5: METIS ordering where MUMPS has it (as for the Amesos
    /// path). Debian's MUMPS 5.5 is built without METIS and SCOTCH: it
    /// takes PORD, its own nested dissection (ICNTL(7) = 4), and says so
    /// only in the messages switched off below.
    constexpr int metis_ordering = 5;
    /// ICNTL(14): 50 % workspace margin over the analysis's estimate...
    constexpr int workspace_margin_percent = 50;
    /// ... doubled this many times at most where the factorisation needs
    /// more (INFOG(1) = -8, -9: more delayed pivots than the analysis
    /// foresaw, as an indefinite tangent may have).
    constexpr unsigned int workspace_retries           = 4;
    constexpr int          workarray_too_small_integer = -8;
    constexpr int          workarray_too_small_real    = -9;
  } // namespace

  SymmetricMumps::SymmetricMumps()
  {
    id              = DMUMPS_STRUC_C();
    id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
    id.par          = 1; // the host works too
    id.sym          = symmetric_indefinite;
    call(job_init);
    // No messages of MUMPS's own: a failure is reported by the caller, with
    // INFOG(1) and INFOG(2).
    id.icntl[0]  = -1;
    id.icntl[1]  = -1;
    id.icntl[2]  = -1;
    id.icntl[3]  = 0;
    id.icntl[6]  = metis_ordering;
    id.icntl[13] = workspace_margin_percent;
  }

  SymmetricMumps::~SymmetricMumps()
  {
    call(job_end);
  }

  void
  SymmetricMumps::call(const int job)
  {
    id.job = job;
    dmumps_c(&id);
  }

  void
  SymmetricMumps::copy_lower_triangle(const Epetra_CrsMatrix &A,
                                      const bool              with_pattern)
  {
    if (with_pattern)
      {
        rows.clear();
        columns.clear();
        values.clear();
      }
    std::size_t i = 0;
    for (int r = 0; r < A.NumMyRows(); ++r)
      {
        int     n;
        double *v;
        int    *c;
        A.ExtractMyRowView(r, n, v, c);
        const long long row = A.GRID64(r);
        for (int k = 0; k < n; ++k)
          {
            const long long column = A.GCID64(c[k]);
            if (column > row)
              continue;
            if (with_pattern)
              {
                rows.push_back(static_cast<MUMPS_INT>(row + 1));
                columns.push_back(static_cast<MUMPS_INT>(column + 1));
                values.push_back(v[k]);
              }
            else
              values[i++] = v[k];
          }
      }
  }

  int
  SymmetricMumps::factorise(const Epetra_CrsMatrix &A)
  {
    if (!analysed || A.NumMyNonzeros() != pattern_entries)
      {
        copy_lower_triangle(A, true);
        pattern_entries = A.NumMyNonzeros();
        id.n            = static_cast<MUMPS_INT>(A.NumGlobalRows64());
        id.nnz          = static_cast<MUMPS_INT8>(rows.size());
        id.irn          = rows.data();
        id.jcn          = columns.data();
        id.a            = values.data();
        call(job_analyse);
        analysed = id.infog[0] >= 0;
        if (!analysed)
          return id.infog[0];
      }
    else
      copy_lower_triangle(A, false);
    id.icntl[13] = workspace_margin_percent;
    call(job_factorise);
    for (unsigned int retry = 0; retry < workspace_retries &&
                                 (id.infog[0] == workarray_too_small_integer ||
                                  id.infog[0] == workarray_too_small_real);
         ++retry)
      {
        id.icntl[13] *= 2;
        call(job_factorise);
      }
    return id.infog[0];
  }

  int
  SymmetricMumps::solve(double *x)
  {
    id.rhs  = x;
    id.nrhs = 1;
    id.lrhs = id.n;
    call(job_solve);
    return id.infog[0];
  }

  int
  SymmetricMumps::error() const
  {
    return id.infog[0];
  }

  int
  SymmetricMumps::error_detail() const
  {
    return id.infog[1];
  }
} // namespace RestShape
