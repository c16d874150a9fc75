// OpenBLAS (MUMPS's dense kernels) follows deal.II's thread count: with
// DEAL_II_NUM_THREADS=1, or two MPI ranks on two cores, it must not start a
// thread per core of its own (found running two stability cases side by
// side: each process had an OpenBLAS thread in dgemm next to its main
// thread). Factorisations of fewer than blas_threads_min_unknowns unknowns
// take one thread (a second one spins between MUMPS's BLAS calls there),
// larger ones deal.II's count. A user's OPENBLAS_NUM_THREADS is left alone.
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <dlfcn.h>
#include <restshape/base/mpi_start.h>
#include <restshape/solver/linear_solver.h>

#include <cstdlib>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

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
  check_between("count returned", match_blas_threads_to_deal_ii(), 1, 1);
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

  // The user's OPENBLAS_NUM_THREADS wins.
  set(2);
  setenv("OPENBLAS_NUM_THREADS", "2", 1);
  check_between("with OPENBLAS_NUM_THREADS: count returned",
                match_blas_threads_to_deal_ii(),
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
