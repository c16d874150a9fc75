#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <dlfcn.h>
#include <restshape/base/input_error.h>
#include <restshape/solver/block_preconditioner.h>
#include <restshape/solver/linear_solver.h>
#include <restshape/solver/pressure_coupling.h>
#include <restshape/solver/split_tangent.h>
#include <restshape/solver/symmetric_mumps.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#ifdef __GLIBC__
#  include <malloc.h>
#endif

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    using SetThreads = void (*)(int);
    /// OpenBLAS's openblas_set_num_threads, or nullptr where the user set
    /// OPENBLAS_NUM_THREADS or OpenBLAS is not loaded. Looked up at run
    /// time: OpenBLAS comes in through deal.II's and MUMPS's dependencies
    /// (Debian's BLAS alternative), not our link line.
    SetThreads
    blas_thread_setter()
    {
      if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr)
        return nullptr;
      return reinterpret_cast<SetThreads>(
        dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    }
  } // namespace

  unsigned int
  set_blas_threads_for(const types::global_dof_index factorised_unknowns)
  {
    const SetThreads set = blas_thread_setter();
    if (set == nullptr)
      return 0;
    const unsigned int n = factorised_unknowns >= blas_threads_min_unknowns ?
                             MultithreadInfo::n_threads() :
                             1;
    set(static_cast<int>(n));
    return n;
  }

  LinearSolver::LinearSolver(const SolverParameters &parameters,
                             const unsigned int      degree,
                             TimerOutput            *timer)
    : parameters(parameters)
    , degree(degree)
    , timer(timer)
  {}

  LinearSolver::~LinearSolver() = default;

  void
  LinearSolver::set_rigid_body_modes(std::vector<std::vector<double>> modes)
  {
    rigid_body_modes = std::move(modes);
  }

  void
  LinearSolver::set_pressure_coupling(const PressureCoupling *c)
  {
    coupling = c;
  }

  bool
  LinearSolver::uses_block() const
  {
    return coupling != nullptr && coupling->n_global() > 0;
  }

  std::string
  LinearSolver::preconditioner_name() const
  {
    return uses_block() ? "block AMG" : "AMG";
  }

  void
  LinearSolver::set_split_tangent(SplitTangent *s)
  {
    split = s;
  }

  bool
  LinearSolver::uses_split(const MatrixType &A) const
  {
    return split != nullptr && !uses_block() && split->applies(A);
  }

  const Epetra_RowMatrix &
  LinearSolver::amg_rows(const MatrixType &A)
  {
    if (uses_split(A))
      return *split;
    return amg_target(A).trilinos_matrix();
  }

  const MatrixType &
  LinearSolver::amg_target(const MatrixType &A)
  {
    if (!uses_block())
      return A;
    coupling->displacement_block(A, displacement_block);
    block_diagonal.reinit(A.locally_owned_domain_indices(),
                          A.get_mpi_communicator());
    for (const auto i : block_diagonal.locally_owned_elements())
      block_diagonal[i] = displacement_block.diag_element(i);
    block_diagonal.compress(VectorOperation::insert);
    return displacement_block;
  }

  void
  LinearSolver::set_symmetric(const bool s)
  {
    symmetric = s;
  }

  unsigned int
  LinearSolver::solve(const MatrixType &A,
                      VectorType       &x,
                      const VectorType &b,
                      const double      relative_tolerance)
  {
    last_matrix = &A;
    if (!solves_prepared_exactly())
      try
        {
          return solve_iteratively(A,
                                   x,
                                   b,
                                   relative_tolerance > 0 ?
                                     relative_tolerance :
                                     parameters.linear_tolerance);
        }
      catch (const SolverFailure &failure)
        {
          switch_to_direct(failure);
        }

    solve_directly(A, x, b);
    for (const double v : x)
      if (!std::isfinite(v))
        throw SolverFailure("the direct solver (MUMPS) returned NaN: the "
                            "matrix is singular (check that the scene fixes "
                            "every rigid-body motion)");
    last_method = fell_back ? "MUMPS after CG+AMG failed" : "MUMPS";
    return 1;
  }

  void
  LinearSolver::allow_direct_fallback()
  {
    direct_fallback_allowed = true;
  }

  void
  LinearSolver::switch_to_direct(const SolverFailure &failure)
  {
    // Called in the handler of @p failure: without the fallback, rethrow it.
    if (!direct_fallback_allowed)
      throw;
    fell_back                = true;
    const std::string reason = failure.what();
    amg.reset();
    amg_matrix = nullptr;
    // The failure's advice (to set the direct solver) is what happens here.
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "  Linear solver: CG + AMG failed ("
                << reason.substr(0, reason.find("; try"))
                << "); the direct solver takes over for the rest of the run"
                << std::endl;
  }

  void
  LinearSolver::solve_directly(const MatrixType &A,
                               VectorType       &x,
                               const VectorType &b)
  {
    factorise(A);
    solve_prepared(x, b);
  }

  void
  LinearSolver::factorise_symmetric(const Epetra_CrsMatrix &matrix,
                                    const bool              new_matrix)
  {
    if (new_matrix || symmetric_direct == nullptr)
      symmetric_direct = std::make_unique<SymmetricMumps>();
    factored_matrix  = &matrix;
    const int status = symmetric_direct->factorise(matrix);
    if (status < 0)
      throw SolverFailure(
        "the direct solver (MUMPS, LDL^T) could not factorise the matrix "
        "with " +
        std::to_string(matrix.NumGlobalRows64()) + " unknowns (error " +
        std::to_string(status) + ", " +
        std::to_string(symmetric_direct->error_detail()) +
        "): singular matrix? check that the scene fixes every rigid-body "
        "motion");
  }

  void
  LinearSolver::factorise(const MatrixType &A)
  {
    Epetra_CrsMatrix &matrix =
      const_cast<Epetra_CrsMatrix &>(A.trilinos_matrix());
    set_blas_threads_for(A.m());
    // Direct factorisation = ldlt, one process and a symmetric tangent:
    // MUMPS's LDL^T (SymmetricMumps).
    if (parameters.symmetric_factorisation && symmetric &&
        matrix.Comm().NumProc() == 1)
      {
        direct_solver.reset();
        direct_problem.reset();
        factorise_symmetric(matrix, factored_matrix != &matrix);
        return;
      }
    symmetric_direct.reset();
    if (factored_matrix != &matrix || direct_solver == nullptr)
      {
        // New matrix object (new mesh): new symbolic factorisation.
        direct_solver.reset();
        direct_problem = std::make_unique<Epetra_LinearProblem>();
        direct_problem->SetOperator(&matrix);
        Amesos factory;
        direct_solver.reset(factory.Create("Amesos_Mumps", *direct_problem));
        AssertThrow(direct_solver != nullptr,
                    ExcMessage("MUMPS is not available in Amesos"));
        Teuchos::ParameterList list;
        // No messages of Amesos's own: a failed factorisation is one
        // SolverFailure with its figures, not five INFOG lines on stderr.
        list.set("OutputLevel", 0);
        // Amesos passes MUMPS the whole matrix with SYM = 0 whatever its
        // MatrixProperty says (Trilinos bugs 2331/2332): MUMPS factorises
        // LU, symmetric or not (measured: the same flops either way).
        direct_solver->SetParameters(list);
        auto *mumps = dynamic_cast<Amesos_Mumps *>(direct_solver.get());
        mumps->SetICNTL(7, 5);   // METIS (Debian's MUMPS: PORD)
        mumps->SetICNTL(14, 50); // 50 % workspace margin
        if (direct_solver->SymbolicFactorization() != 0)
          throw SolverFailure("MUMPS: symbolic factorisation failed");
        factored_matrix = &matrix;
      }
    const int status = direct_solver->NumericFactorization();
    if (status != 0)
      throw SolverFailure("the direct solver (MUMPS) could not factorise the "
                          "matrix with " +
                          std::to_string(A.m()) + " unknowns (error " +
                          std::to_string(status) +
                          "): singular matrix? check that the scene fixes "
                          "every rigid-body motion");
  }

  void
  LinearSolver::prepare(const MatrixType &A)
  {
    last_matrix = &A;
    if (!solves_prepared_exactly())
      setup_amg(A, AmgSetup::as_configured);
    else
      factorise(A);
  }

  bool
  LinearSolver::solves_prepared_exactly() const
  {
    return parameters.linear_solver != LinearSolverType::cg_amg || fell_back;
  }

  void
  LinearSolver::release()
  {
    direct_solver.reset();
    direct_problem.reset();
    symmetric_direct.reset();
    factored_matrix = nullptr;
    last_matrix     = nullptr;
    amg.reset(); // before its null space
    null_space.reset();
    displacement_block.clear();
    amg_matrix                = nullptr;
    amg_built_on              = nullptr;
    amg_iterations_per_decade = 0;
    amg_stale                 = false;
#ifdef __GLIBC__
    // The freed pages go back to the system: the threads of the next work
    // (the error estimator) allocate from their own arenas and would not
    // reuse them.
    malloc_trim(0);
#endif
  }

  void
  LinearSolver::solve_prepared(VectorType       &x,
                               const VectorType &b,
                               const double      tolerance)
  {
    AssertThrow(last_matrix != nullptr,
                ExcMessage("solve_prepared() needs a solve or prepare first"));
    if (!solves_prepared_exactly())
      try
        {
          x = 0;
          solve_iteratively(*last_matrix, x, b, tolerance);
          return;
        }
      catch (const SolverFailure &failure)
        {
          switch_to_direct(failure);
          factorise(*last_matrix);
        }
    if (symmetric_direct != nullptr)
      {
        x                = b;
        const int status = symmetric_direct->solve(x.trilinos_vector()[0]);
        if (status < 0)
          throw SolverFailure("the direct solver (MUMPS, LDL^T) could not "
                              "solve (error " +
                              std::to_string(status) + ")");
        return;
      }
    AssertThrow(direct_solver != nullptr,
                ExcMessage("solve_prepared() needs a factorisation first"));
    direct_problem->SetLHS(&x.trilinos_vector());
    direct_problem->SetRHS(const_cast<Epetra_MultiVector *>(
      static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
    direct_solver->Solve();
  }

  bool
  LinearSolver::setup_amg(const MatrixType &A, const AmgSetup how)
  {
    std::unique_ptr<TimerOutput::Scope> scope;
    if (timer != nullptr)
      scope = std::make_unique<TimerOutput::Scope>(*timer, "AMG set-up");
    const bool same_matrix =
      amg != nullptr && amg_matrix == &A.trilinos_matrix();
    // The rows the AMG is built on, once computed.
    const Epetra_RowMatrix *target = nullptr;
    if (same_matrix && how == AmgSetup::as_configured)
      switch (parameters.amg_update)
        {
          case AmgUpdate::reuse_aggregates:
            // Same sparsity pattern, new values: keep the aggregates (of
            // the same displacement block object, refilled in place).
            target = &amg_rows(A);
            if (target == amg_built_on)
              {
                amg->reinit();
                return true;
              }
            break;
          case AmgUpdate::lagged:
            if (!amg_stale)
              return false;
            break;
          case AmgUpdate::rebuild:
            break;
        }

    amg.reset(); // before its null space goes
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = (degree > 1);
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = parameters.amg_aggregation_threshold;

    if (target == nullptr)
      target = &amg_rows(A);
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> unused;
    data.set_parameters(list, unused, *target);

    // ML's name for the prolongator smoothing: 4/3 by default, 0 for plain
    // aggregation.
    if (!parameters.amg_smoothed_aggregation)
      list.set("aggregation: damping factor", 0.0);

    // Without modes, ML's default null space (the constants); Epetra
    // refuses a multivector of no vectors.
    if (!rigid_body_modes.empty())
      {
        const Epetra_Map &map = target->OperatorDomainMap();
        null_space =
          std::make_unique<Epetra_MultiVector>(map, rigid_body_modes.size());
        for (unsigned int m = 0; m < rigid_body_modes.size(); ++m)
          for (int i = 0; i < map.NumMyElements(); ++i)
            (*null_space)[m][i] = rigid_body_modes[m][i];
        list.set("null space: type", "pre-computed");
        list.set("null space: dimension", null_space->NumVectors());
        list.set("null space: vectors", null_space->Values());
      }
    amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    amg->initialize(*target, list);
    amg_matrix   = &A.trilinos_matrix();
    amg_built_on = target;
    amg_stale    = false;
    return true;
  }

  namespace
  {
    /// GMRES preconditioned from the right: it then measures the residual
    /// itself, not the preconditioned one (which a poor AMG can make look
    /// converged after one iteration).
    constexpr bool right_preconditioning = true;

    /// CG iterations per decade of residual reduction of a finished solve
    /// (0 if it reduced the residual too little to tell).
    double
    iterations_per_decade(const SolverControl &control, const VectorType &b)
    {
      const double decades =
        std::log10(b.l2_norm() / std::max(control.last_value(), 1e-300));
      return decades > 0.3 ? control.last_step() / decades : 0.;
    }
  } // namespace

  unsigned int
  LinearSolver::lagged_iteration_cap(const VectorType &b,
                                     const VectorType &x,
                                     const MatrixType &A,
                                     const double      target) const
  {
    if (amg_iterations_per_decade == 0)
      return max_cg_iterations;
    VectorType r = b;
    if (x.linfty_norm() > 0)
      {
        A.vmult(r, x);
        r.sadd(-1., b);
      }
    const double decades =
      std::max(1., std::log10(r.l2_norm() / std::max(target, 1e-300)));
    return std::clamp(static_cast<unsigned int>(
                        std::ceil(lagged_slowdown_cap *
                                  amg_iterations_per_decade * decades)),
                      min_lagged_iterations,
                      max_cg_iterations);
  }

  unsigned int
  LinearSolver::solve_iteratively(const MatrixType &A,
                                  VectorType       &x,
                                  const VectorType &b,
                                  const double      relative_tolerance)
  {
    set_blas_threads_for(no_factorisation);
    if (uses_split(A))
      split->refresh_diagonal(); // a Newton step's shift
    const double target = relative_tolerance * b.l2_norm();
    if (setup_amg(A, AmgSetup::as_configured))
      return run_krylov(A, x, b, target);

    // Lagged AMG (an earlier step's): CG with it, bounded by what the AMG
    // needed when built. If CG has slowed down by more than 1.5 times, the
    // next solve rebuilds; if CG needs more than lagged_slowdown_cap times
    // (or fails), this one rebuilds and solves again.
    SolverControl control(lagged_iteration_cap(b, x, A, target), target);
    if (run_cg(A, x, b, control))
      {
        const double now = iterations_per_decade(control, b);
        if (amg_iterations_per_decade == 0)
          amg_iterations_per_decade = now;
        else if (now > 1.5 * amg_iterations_per_decade)
          amg_stale = true;
        return control.last_step();
      }
    setup_amg(A, AmgSetup::rebuild);
    return control.last_step() + run_krylov(A, x, b, target);
  }

  BlockPreconditioner
  LinearSolver::make_preconditioner()
  {
    if (!uses_block())
      return BlockPreconditioner(*amg, nullptr, inverse_schur);
    inverse_schur = coupling->inverse_schur_diagonal(block_diagonal);
    return BlockPreconditioner(*amg, coupling, inverse_schur);
  }

  bool
  LinearSolver::run_cg(const MatrixType &A,
                       VectorType       &x,
                       const VectorType &b,
                       SolverControl    &control)
  {
    const BlockPreconditioner preconditioner = make_preconditioner();
    const std::string         amg_name       = preconditioner_name();
    try
      {
        if (symmetric)
          {
            // The product by A: the split's where it applies.
            SolverCG<VectorType> cg(control);
            if (uses_split(A))
              cg.solve(*split, x, b, preconditioner);
            else
              cg.solve(A, x, b, preconditioner);
            last_method = "CG+" + amg_name;
          }
        else
          {
            SolverGMRES<VectorType> gmres(
              control,
              SolverGMRES<VectorType>::AdditionalData(200,
                                                      right_preconditioning));
            gmres.solve(A, x, b, preconditioner);
            last_method = "GMRES+" + amg_name;
          }
        return true;
      }
    catch (const SolverControl::NoConvergence &)
      {
        x = 0;
        return false;
      }
  }

  unsigned int
  LinearSolver::run_krylov(const MatrixType &A,
                           VectorType       &x,
                           const VectorType &b,
                           const double      target)
  {
    SolverControl control(max_cg_iterations, target);
    if (run_cg(A, x, b, control))
      {
        // The standard a lagged AMG is held to.
        amg_iterations_per_decade = iterations_per_decade(control, b);
        return control.last_step();
      }
    // What a failure says: the iterations, the residual and the target.
    const auto failure = [&](const std::string &iterations,
                             const double       residual) {
      return "the iterative solver did not converge: " + iterations +
             " iterations with residual " + std::to_string(residual) +
             " (target " + std::to_string(target) + ")";
    };
    const std::string first_iterations = std::to_string(control.last_step());
    if (direct_fallback_allowed && A.m() <= direct_fallback_dofs)
      throw SolverFailure(failure(std::string(symmetric ? "CG" : "GMRES") +
                                    " stopped after " + first_iterations,
                                  control.last_value()));
    // The consistent co-rotational tangent can be indefinite at large
    // strains: GMRES does not need definiteness.
    SolverControl gmres_control(max_gmres_iterations, target);
    try
      {
        SolverGMRES<VectorType> gmres(
          gmres_control,
          SolverGMRES<VectorType>::AdditionalData(200, right_preconditioning));
        gmres.solve(A, x, b, make_preconditioner());
      }
    catch (const SolverControl::NoConvergence &exc)
      {
        throw SolverFailure(failure("CG stopped after " + first_iterations +
                                      " and GMRES after " +
                                      std::to_string(exc.last_step),
                                    exc.last_residual) +
                            "; try Linear solver = direct");
      }
    last_method = "GMRES+" + preconditioner_name();
    return control.last_step() + gmres_control.last_step();
  }
} // namespace RestShape
