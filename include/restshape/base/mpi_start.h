// How the programs start MPI: fast when run without an MPI launcher.
#ifndef restshape_mpi_start_h
#define restshape_mpi_start_h

namespace RestShape
{
  /**
   * True if an MPI launcher (mpirun/mpiexec of Open MPI or MPICH, PMIx,
   * PMI or Slurm's srun) started this process: it then has variables such
   * as OMPI_COMM_WORLD_SIZE, PMIX_RANK or PMI_RANK.
   */
  bool
  started_by_mpi_launcher();

  /**
   * Call before MPI_Init (MPI_InitFinalize). A program run without a
   * launcher is an MPI "singleton"; Open MPI 4 then starts a runtime daemon
   * (orted) and probes every network transport, which takes 0.3 s of
   * every run (measured on the CI machine: MPI_Init alone 0.31 s). For a
   * singleton this sets Open MPI's ess_singleton_isolated = 1 (no daemon)
   * and pml = ob1 (the point-to-point layer over the shared-memory and
   * self transports, all one process needs): MPI_Init then takes 0.02 s.
   * Variables the user set are kept; launched runs are left alone; other
   * MPI libraries ignore these variables. Returns whether it set any.
   */
  bool
  prefer_fast_singleton_mpi();
} // namespace RestShape

#endif
