// Linear solves of the Newton systems: sparse direct or CG + ML AMG.
#ifndef restshape_linear_solver_h
#define restshape_linear_solver_h

#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <restshape/base/parameters.h>

#include <memory>
#include <string>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;
class Epetra_MultiVector;

namespace RestShape
{
  /**
   * OpenBLAS (which MUMPS factorises with) starts one thread per core of its
   * own, whatever DEAL_II_NUM_THREADS or the number of MPI ranks on a node
   * say. Sets OpenBLAS's thread count to deal.II's
   * (MultithreadInfo::n_threads(), which MPI_InitFinalize splits among the
   * ranks of a node), unless OPENBLAS_NUM_THREADS is set. Returns the
   * count set, 0 if it left OpenBLAS alone (variable set, or no OpenBLAS
   * loaded).
   */
  unsigned int
  match_blas_threads_to_deal_ii();

  using VectorType = dealii::TrilinosWrappers::MPI::Vector;
  using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

  class LinearSolver
  {
  public:
    /// @p timer, if given, gets a section "AMG set-up" (inside the
    /// caller's "Linear solve").
    LinearSolver(const SolverParameters &parameters,
                 const unsigned int      degree,
                 dealii::TimerOutput    *timer = nullptr);
    ~LinearSolver();

    /**
     * The six rigid-body modes (three translations, three rotations), each
     * with one value per locally owned degree of freedom, in the order of
     * the locally owned index set. Used as AMG null space.
     */
    void
    set_rigid_body_modes(std::vector<std::vector<double>> modes);

    /// Whether the matrices are symmetric (default): the Krylov method is
    /// then CG, otherwise GMRES.
    void
    set_symmetric(const bool symmetric);

    /**
     * Solve A x = b. Returns the number of iterations (1 for the direct
     * solver). The iterative solver reduces the residual by
     * @p relative_tolerance (0: Solver/Linear solver tolerance). Throws
     * SolverFailure with the figures if it cannot.
     */
    unsigned int
    solve(const MatrixType &A,
          VectorType       &x,
          const VectorType &b,
          const double      relative_tolerance = 0);

    /**
     * Solve A x = b with the factorisation of the last direct solve (of
     * the same matrix A): the direct solver only, for many right-hand
     * sides.
     */
    void
    solve_factored(VectorType &x, const VectorType &b);

    /// Which method solved the last system ("MUMPS", "CG+AMG", "GMRES+AMG").
    std::string last_method;

  private:
    unsigned int
    solve_iteratively(const MatrixType &A,
                      VectorType       &x,
                      const VectorType &b,
                      const double      relative_tolerance);
    void
    solve_directly(const MatrixType &A, VectorType &x, const VectorType &b);

    /// Makes the AMG preconditioner for @p A as Solver/AMG update says: a
    /// new build, a recomputation on the aggregates of the first build, or
    /// (lagged) the existing one. Returns true if it built or recomputed.
    bool
    setup_amg(const MatrixType &A, const bool force_rebuild);

    /// CG (GMRES for a non-symmetric matrix) with the current AMG under
    /// @p control; false (and x = 0) if it does not converge.
    bool
    run_cg(const MatrixType      &A,
           VectorType            &x,
           const VectorType      &b,
           dealii::SolverControl &control);

    /// CG (GMRES if CG breaks down) with the current AMG; throws
    /// SolverControl::NoConvergence if both fail.
    unsigned int
    run_krylov(const MatrixType &A,
               VectorType       &x,
               const VectorType &b,
               const double      target);

    /// MUMPS, kept between solves with the same matrix object so that the
    /// symbolic factorisation (METIS ordering) is done once per mesh.
    std::unique_ptr<Epetra_LinearProblem> direct_problem;
    std::unique_ptr<Amesos_BaseSolver>    direct_solver;
    const void                           *factored_matrix = nullptr;

    /// AMG, kept between solves with the same matrix object (the tangent
    /// of one mesh); its null space (the rigid-body modes) must outlive it.
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
    std::unique_ptr<Epetra_MultiVector>                        null_space;
    const void *amg_matrix = nullptr;
    /// Lagged AMG: CG iterations per decade of residual reduction in the
    /// first solve after the last build, and whether the next solve must
    /// rebuild.
    double amg_iterations_per_decade = 0;
    bool   amg_stale                 = false;

    const SolverParameters           parameters;
    const unsigned int               degree;
    bool                             symmetric = true;
    dealii::TimerOutput             *timer;
    std::vector<std::vector<double>> rigid_body_modes;
  };
} // namespace RestShape

#endif
