#include <restshape/base/mpi_start.h>

#include <cstdlib>

namespace RestShape
{
  namespace
  {
    /// Variables that launchers set in the processes they start.
    constexpr const char *launcher_variables[] = {
      "OMPI_COMM_WORLD_SIZE", // Open MPI's mpirun
      "PMIX_RANK",            // PMIx (Open MPI 4/5, Slurm with PMIx)
      "PMI_RANK",             // MPICH's Hydra, Slurm with PMI-2
      "PMI_SIZE",
      "PMI_FD",
      "MPI_LOCALRANKID", // Intel MPI, MPICH
      "SLURM_STEP_ID"};  // any srun step

    /// Open MPI's MCA parameters for a singleton, name and value.
    struct Setting
    {
      const char *name;
      const char *value;
    };
    /// Isolated singletons of Open MPI 4 all share one session directory
    /// (/tmp/ompi.HOST.UID/jf.0/1): a run that ends removes it while another
    /// one starts, whose MPI_Init then fails ("A call to mkdir was unable to
    /// create the desired directory", exit 1; 5 of 480 starts of 8 at a
    /// time). A singleton needs no session directory, so none is made.
    constexpr Setting singleton_settings[] = {
      {"OMPI_MCA_ess_singleton_isolated", "1"},
      {"OMPI_MCA_pml", "ob1"},
      {"OMPI_MCA_orte_create_session_dirs", "0"}};
  } // namespace

  bool
  started_by_mpi_launcher()
  {
    for (const char *name : launcher_variables)
      if (std::getenv(name) != nullptr)
        return true;
    return false;
  }

  bool
  prefer_fast_singleton_mpi()
  {
    if (started_by_mpi_launcher())
      return false;
    bool set = false;
    for (const auto &[name, value] : singleton_settings)
      if (std::getenv(name) == nullptr)
        {
          setenv(name, value, 0);
          set = true;
        }
    return set;
  }
} // namespace RestShape
