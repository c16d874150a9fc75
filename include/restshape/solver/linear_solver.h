// Linear solves of the Newton systems: sparse direct or CG + ML AMG.
#ifndef restshape_solver_linear_solver_h
#define restshape_solver_linear_solver_h

#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <restshape/base/linear_algebra_types.h>
#include <restshape/solver/solver_parameters.h>

#include <memory>
#include <string>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;
class Epetra_MultiVector;
class Epetra_RowMatrix;

namespace RestShape
{
  class SolverFailure; // restshape/base/input_error.h

  /**
   * OpenBLAS (which MUMPS factorises with) starts one thread per core of its
   * own, whatever DEAL_II_NUM_THREADS or the number of MPI ranks on a node
   * say, and an idle one spins in sched_yield between BLAS calls, taking a
   * core from the assembly's threads, another rank or another run. It gets
   * deal.II's count (MultithreadInfo::n_threads(), which MPI_InitFinalize
   * splits among the ranks of a node) only to factorise systems of at least
   * blas_threads_min_unknowns unknowns (and for the direct solves with that
   * factorisation), one thread otherwise. On a 2-core AMD EPYC, 2 threads
   * against 1: MUMPS on the P2 strip of 9,045 DoFs
   * (tests/unit/contact/peeling_strip.cc) 55.5 against 49.7 s, twice the
   * CPU time; P2 brain of 25,173 DoFs on the skull 36.2 against 41.7 s; Q2
   * hemisphere of 77,763 DoFs 81 against 125 s. CG + AMG (Epetra's vector
   * operations) on 202,095 DoFs: 49.4 against 50.1 s, with 24.2 against
   * 0.7 s of system time.
   */
  constexpr dealii::types::global_dof_index blas_threads_min_unknowns = 20000;

  /// What set_blas_threads_for() is given outside factorisations: the
  /// start of a run, iterative solves.
  constexpr dealii::types::global_dof_index no_factorisation = 0;

  /**
   * Before a factorisation of a system of @p factorised_unknowns unknowns
   * (or with no_factorisation before other work): OpenBLAS's thread count
   * to deal.II's from blas_threads_min_unknowns up, to 1 below. Returns the
   * count set, 0 if it left OpenBLAS alone (OPENBLAS_NUM_THREADS set, or no
   * OpenBLAS loaded).
   */
  unsigned int
  set_blas_threads_for(
    const dealii::types::global_dof_index factorised_unknowns);

  class SymmetricMumps;
  class PressureCoupling;
  class BlockPreconditioner;
  class SplitTangent;

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

    /**
     * The pressure unknowns the matrices of the mixed formulation have
     * condensed (nullptr: none), as the assembly of each matrix leaves
     * them. CG + AMG then builds its AMG on the displacement block and
     * preconditions with the block factorisation (BlockPreconditioner).
     */
    void
    set_pressure_coupling(const PressureCoupling *coupling);

    /**
     * The averaged nodal pressure's tangent as its narrow matrix and
     * rank-one terms (nullptr: none), as each assembly leaves it. CG + AMG
     * (without the block preconditioner) then applies the matrices it
     * applies (SplitTangent::applies()) through it, in CG and in ML's
     * finest level; the direct solver uses the matrix.
     */
    void
    set_split_tangent(SplitTangent *split);

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
     * Prepare solves with @p A for many right-hand sides (solve_prepared()):
     * the direct solver factorises it, CG + AMG sets up (or, lagged, keeps)
     * its AMG. Throws SolverFailure if the factorisation fails.
     */
    void
    prepare(const MatrixType &A);

    /**
     * Solve A x = b with the matrix of the last solve() or prepare(): the
     * direct solver with its factorisation (exact), CG + AMG to the
     * relative tolerance @p tolerance (by default prepared_solve_tolerance:
     * an inexact solve, for preconditioners inside a flexible Krylov
     * method).
     */
    void
    solve_prepared(VectorType       &x,
                   const VectorType &b,
                   const double      tolerance = prepared_solve_tolerance);

    /// Whether solve_prepared() solves exactly (the direct solver).
    bool
    solves_prepared_exactly() const;

    /// Free the factorisation (symbolic too) and the AMG; the next solve or
    /// prepare() builds them again.
    void
    release();

    /// The relative tolerance of solve_prepared() with CG + AMG.
    static constexpr double prepared_solve_tolerance = 1e-3;

    /// Linear solver = auto took CG + AMG: where CG and GMRES fail on a
    /// system, solve it and every later one with the direct solver; on
    /// systems of at most direct_fallback_dofs unknowns, where CG fails
    /// (GMRES is not tried).
    void
    allow_direct_fallback();

    /// Which method solved the last system ("MUMPS", "CG+AMG", "GMRES+AMG",
    /// "MUMPS after CG+AMG failed").
    std::string last_method;

  private:
    unsigned int
    solve_iteratively(const MatrixType &A,
                      VectorType       &x,
                      const VectorType &b,
                      const double      relative_tolerance);
    void
    solve_directly(const MatrixType &A, VectorType &x, const VectorType &b);
    /// In the handler of @p failure of an iterative solve: solve with the
    /// direct solver from now on if allow_direct_fallback() was called,
    /// rethrow it otherwise.
    void
    switch_to_direct(const SolverFailure &failure);
    /// MUMPS's (symbolic, when A is new, and) numeric factorisation of A.
    void
    factorise(const MatrixType &A);
    /// The same with SymmetricMumps (analysed anew for a new matrix).
    void
    factorise_symmetric(const Epetra_CrsMatrix &matrix, const bool new_matrix);

    /// The most CG iterations a lagged AMG may take for A x = b from the
    /// current x down to @p target: lagged_slowdown_cap times the
    /// iterations per decade of its first solve, at least
    /// min_lagged_iterations (max_cg_iterations before any solve).
    unsigned int
    lagged_iteration_cap(const VectorType &b,
                         const VectorType &x,
                         const MatrixType &A,
                         const double      target) const;

    /// Krylov iteration limits: CG with a new AMG, then GMRES(200) if CG
    /// breaks down (indefinite tangent).
    static constexpr unsigned int max_cg_iterations    = 2000;
    static constexpr unsigned int max_gmres_iterations = 5000;
    /// With the direct fallback allowed, systems of at most this many
    /// unknowns go to the direct solver as soon as CG fails, without
    /// GMRES's 5000 iterations first: MUMPS solves them in seconds (the
    /// column's 132k P1 DoFs in 12 s a solve), while GMRES after a failed
    /// CG seldom converges (step-44's block at nu = 0.4999, 14,739 DoFs:
    /// CG 2000 and GMRES 5000 iterations failed, 56 s in all against the
    /// direct solver's 23 s). Larger systems try GMRES first, as the
    /// direct solver's memory may not be at hand.
    static constexpr unsigned int direct_fallback_dofs = 150000;
    /// A lagged AMG is rebuilt at once when CG would need more than this
    /// many times its iterations per decade when it was built.
    static constexpr double       lagged_slowdown_cap   = 3;
    static constexpr unsigned int min_lagged_iterations = 30;

    /// Makes the AMG preconditioner for @p A as Solver/AMG update says: a
    /// new build, a recomputation on the aggregates of the first build, or
    /// (lagged) the existing one; AmgSetup::rebuild builds it anew
    /// whatever it says. Returns true if it built or recomputed.
    enum class AmgSetup
    {
      as_configured,
      rebuild
    };
    bool
    setup_amg(const MatrixType &A, const AmgSetup how);
    /// Whether the AMG works on the displacement block of a mixed system.
    bool
    uses_block() const;
    /// "block AMG" or "AMG", as the Newton lines name the preconditioner.
    std::string
    preconditioner_name() const;
    /// The matrix the AMG is built on: A, or its displacement block
    /// (computed anew).
    const MatrixType &
    amg_target(const MatrixType &A);

    /// Whether the split applies @p A (CG + AMG without the block).
    bool
    uses_split(const MatrixType &A) const;
    /// The rows the AMG is built on: the split's (A's) if uses_split(A),
    /// those of amg_target(A) otherwise.
    const Epetra_RowMatrix &
    amg_rows(const MatrixType &A);

    /// The current AMG, in the block preconditioner with the current
    /// pressure coupling if uses_block().
    BlockPreconditioner
    make_preconditioner();

    /// CG (GMRES for a non-symmetric matrix) with the current AMG (in the
    /// block preconditioner with the current pressure coupling) under
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

    /// MUMPS's LDL^T for a symmetric matrix on one process (half the flops
    /// and memory of the LU that Amesos asks for), kept between solves.
    std::unique_ptr<SymmetricMumps> symmetric_direct;
    /// MUMPS, kept between solves with the same matrix object so that the
    /// symbolic factorisation (the fill-reducing ordering) is done once per
    /// mesh.
    std::unique_ptr<Epetra_LinearProblem> direct_problem;
    std::unique_ptr<Amesos_BaseSolver>    direct_solver;
    const void                           *factored_matrix = nullptr;
    /// The matrix of the last solve() or prepare().
    const MatrixType *last_matrix = nullptr;

    /// AMG, kept between solves with the same matrix object (the tangent
    /// of one mesh); its null space (the rigid-body modes) must outlive it.
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
    std::unique_ptr<Epetra_MultiVector>                        null_space;
    const void *amg_matrix = nullptr;
    /// The Epetra matrix the AMG was built on (A's, or the displacement
    /// block's).
    const void *amg_built_on = nullptr;
    /// Lagged AMG: CG iterations per decade of residual reduction in the
    /// first solve after the last build, and whether the next solve must
    /// rebuild.
    double amg_iterations_per_decade = 0;
    bool   amg_stale                 = false;
    /// The block preconditioner's: the pressure unknowns, the displacement
    /// block the AMG was built on and its diagonal, the inverse of the
    /// Schur complement's diagonal approximation (of the last solve).
    const PressureCoupling *coupling = nullptr;
    SplitTangent           *split    = nullptr;
    MatrixType              displacement_block;
    VectorType              block_diagonal, inverse_schur;

    const SolverParameters           parameters;
    bool                             direct_fallback_allowed = false;
    bool                             fell_back               = false;
    const unsigned int               degree;
    bool                             symmetric = true;
    dealii::TimerOutput             *timer;
    std::vector<std::vector<double>> rigid_body_modes;
  };
} // namespace RestShape

#endif
