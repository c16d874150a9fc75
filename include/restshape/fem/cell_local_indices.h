// Each locally owned cell's DoFs by their local index in the assembly's
// distributed vectors (owned entries first, then the ghosts), found once
// per distribution of the DoFs. The assembly reads d and w and adds its
// cell vectors by these indices: converting a global index costs a range
// test and, for a ghost, a search, per entry and per assembly (a profile
// of the P1 brain: 36 conversions and 600 instructions per cell).
#ifndef restshape_fem_cell_local_indices_h
#define restshape_fem_cell_local_indices_h

#include <deal.II/base/partitioner.h>
#include <deal.II/dofs/dof_handler.h>

#include <vector>

namespace RestShape
{
  class CellLocalIndices
  {
  public:
    /// The locally owned cells of @p dof_handler, for vectors of
    /// @p partitioner (which holds all their DoFs).
    void
    reinit(const dealii::DoFHandler<3>               &dof_handler,
           const dealii::Utilities::MPI::Partitioner &partitioner);

    /// The local indices of the DoFs of the owned cell of active index
    /// @p cell, in the order of get_dof_indices().
    void
    get(const unsigned int cell, std::vector<unsigned int> &local) const;

  private:
    unsigned int              dofs_per_cell = 0;
    std::vector<unsigned int> indices; // [active cell index][i]
  };
} // namespace RestShape

#endif
