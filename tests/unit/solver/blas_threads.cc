// OpenBLAS (MUMPS's dense kernels) never takes more threads than deal.II:
// with DEAL_II_NUM_THREADS=1, or two MPI ranks on two cores, it must not
// start a thread per core of its own (found running two stability cases
// side by side: each process had an OpenBLAS thread in dgemm next to its
// main thread). Only factorisations of blas_threads_min_unknowns unknowns
// or more take deal.II's count; smaller ones, iterative solves and the
// start of a run one thread (a second one spins between BLAS calls there).
// A user's OPENBLAS_NUM_THREADS is left alone.
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <dlfcn.h>
#include <restshape/base/mpi_start.h>
#include <restshape/solver/linear_solver.h>

#include <cstdlib>

#include "banded_matrix.h"
#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  /// A 1d Laplacian of @p n unknowns, SPD.
  void
  fill_laplacian(MatrixType &A, const unsigned int n)
  {
    checks::reinit_banded(A, n, 1);
    for (unsigned int i = 0; i < n; ++i)
      {
        A.set(i, i, 2.);
        if (i + 1 < n)
          {
            A.set(i, i + 1, -1.);
            A.set(i + 1, i, -1.);
          }
      }
    A.compress(VectorOperation::insert);
  }

  /// Solves A x = 1 with @p type; the OpenBLAS thread count after it.
  int
  threads_after_solve(const MatrixType      &A,
                      const LinearSolverType type,
                      int (*get)())
  {
    SolverParameters parameters{};
    parameters.linear_solver    = type;
    parameters.linear_tolerance = 1e-8;
    parameters.amg_update       = AmgUpdate::rebuild;
    LinearSolver solver(parameters, 1);
    // No rigid-body modes (a scalar problem): ML's default null space.
    VectorType b(complete_index_set(A.m()), MPI_COMM_WORLD), x(b);
    b = 1.;
    solver.solve(A, x, b);
    return get();
  }
} // namespace

int
main(int argc, char **argv)
{
  unsetenv("OPENBLAS_NUM_THREADS");
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using GetThreads = int (*)();
  using SetThreads = void (*)(int);
  const auto get   = reinterpret_cast<GetThreads>(
    dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  const auto set = reinterpret_cast<SetThreads>(
    dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  check_between("OpenBLAS is loaded (README installs libopenblas0-pthread)",
                get != nullptr && set != nullptr,
                1,
                1);
  if (get == nullptr || set == nullptr)
    return 1;

  // OpenBLAS's own choice on a multicore machine; forced so that the test
  // fails without the fix on any machine.
  set(2);
  check_between("OpenBLAS threads before", get(), 2, 2);
  check_between("deal.II threads (MPI_InitFinalize(..., 1))",
                MultithreadInfo::n_threads(),
                1,
                1);
  check_between("large system under deal.II's 1 thread: count returned",
                set_blas_threads_for(blas_threads_min_unknowns),
                1,
                1);
  check_between("OpenBLAS threads after", get(), 1, 1);

  // By the size of the system factorised, with deal.II's count raised to
  // 2 (where the machine has 2 cores).
  MultithreadInfo::set_thread_limit(2);
  const unsigned int threads = MultithreadInfo::n_threads();
  set(2);
  check_between("small system: count returned",
                set_blas_threads_for(blas_threads_min_unknowns - 1),
                1,
                1);
  check_between("small system: OpenBLAS threads", get(), 1, 1);
  check_between("large system: count returned",
                set_blas_threads_for(blas_threads_min_unknowns),
                threads,
                threads);
  check_between("large system: OpenBLAS threads", get(), threads, threads);
  set(2);
  check_between("no factorisation: count returned",
                set_blas_threads_for(no_factorisation),
                1,
                1);
  check_between("no factorisation: OpenBLAS threads", get(), 1, 1);

  // Through LinearSolver: a direct solve of a system at the threshold
  // factorises with deal.II's count, a CG + AMG solve after it has one
  // thread.
  MatrixType laplacian;
  fill_laplacian(laplacian, blas_threads_min_unknowns);
  set(1);
  check_between("direct solve at the threshold: OpenBLAS threads",
                threads_after_solve(laplacian, LinearSolverType::direct, get),
                threads,
                threads);
  check_between("CG + AMG solve after it: OpenBLAS threads",
                threads_after_solve(laplacian, LinearSolverType::cg_amg, get),
                1,
                1);

  // The user's OPENBLAS_NUM_THREADS wins.
  set(2);
  setenv("OPENBLAS_NUM_THREADS", "2", 1);
  check_between("with OPENBLAS_NUM_THREADS: count returned",
                set_blas_threads_for(blas_threads_min_unknowns),
                0,
                0);
  check_between("with OPENBLAS_NUM_THREADS: OpenBLAS threads", get(), 2, 2);
  check_between("with OPENBLAS_NUM_THREADS: count for a small system",
                set_blas_threads_for(1),
                0,
                0);
  check_between("with OPENBLAS_NUM_THREADS: OpenBLAS threads after it",
                get(),
                2,
                2);
  return exit_code();
}
