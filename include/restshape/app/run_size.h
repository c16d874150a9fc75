// What a scene's mesh size means for the machine, said before the work.
#ifndef restshape_app_run_size_h
#define restshape_app_run_size_h

#include <restshape/app/parameters.h>

#include <cstddef>
#include <string>

namespace RestShape
{
  /// Cells, DoFs and memory of a run on a mesh of @p cells_read cells after
  /// Mesh/Global refinements and @p cycles refinement cycles, estimated
  /// from the element and cell type and the number of MPI ranks.
  struct RunSize
  {
    double cells;
    double dofs;
    double bytes;

    /// "2.7e+06 cells, about 1.6e+06 DoFs and 7.6 GiB".
    std::string
    text() const;
  };

  RunSize
  estimate_run_size(const std::size_t  cells_read,
                    const Parameters  &parameters,
                    const unsigned int cycles);

  /**
   * Throws InputError naming Mesh/Global refinements (or Adaptive
   * refinement/Cycles, if the mesh fits without them) if the refined mesh
   * cannot fit the available memory (the machine's, its cgroup's limit,
   * ulimit -v); prints the estimate on rank 0 when the mesh is refined.
   */
  void
  check_run_size(const std::size_t  cells_read,
                 const Parameters  &parameters,
                 const std::string &prm_file,
                 const bool         print);
} // namespace RestShape

#endif
