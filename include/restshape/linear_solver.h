// Linear solves of the Newton systems: sparse direct or CG + ML AMG.
#ifndef restshape_linear_solver_h
#define restshape_linear_solver_h

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <restshape/parameters.h>

#include <memory>
#include <string>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;
class Epetra_MultiVector;

namespace RestShape
{
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

    /// Builds the AMG preconditioner for @p A, or, with Solver/Reuse AMG
    /// aggregates and the same matrix object as before, recomputes it on
    /// the aggregates of the first build (ML's ReComputePreconditioner).
    void
    setup_amg(const MatrixType &A);

    /// MUMPS, kept between solves with the same matrix object so that the
    /// symbolic factorisation (METIS ordering) is done once per mesh.
    std::unique_ptr<Epetra_LinearProblem> direct_problem;
    std::unique_ptr<Amesos_BaseSolver>    direct_solver;
    const void                           *factored_matrix = nullptr;

    /// AMG, kept between solves with the same matrix object when
    /// Solver/Reuse AMG aggregates is set; its null space (the rigid-body
    /// modes) must outlive it.
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
    std::unique_ptr<Epetra_MultiVector>                        null_space;
    const void *amg_matrix = nullptr;

    const SolverParameters           parameters;
    const unsigned int               degree;
    dealii::TimerOutput             *timer;
    std::vector<std::vector<double>> rigid_body_modes;
  };
} // namespace RestShape

#endif
