#include <restshape/fem/cell_local_indices.h>

namespace RestShape
{
  using namespace dealii;

  void
  CellLocalIndices::reinit(const DoFHandler<3>               &dof_handler,
                           const Utilities::MPI::Partitioner &partitioner)
  {
    dofs_per_cell = dof_handler.get_fe().n_dofs_per_cell();
    indices.assign(std::size_t(
                     dof_handler.get_triangulation().n_active_cells()) *
                     dofs_per_cell,
                   numbers::invalid_unsigned_int);
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          unsigned int *const local =
            &indices[std::size_t(cell->active_cell_index()) * dofs_per_cell];
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            local[i] = partitioner.global_to_local(dofs[i]);
        }
  }

  void
  CellLocalIndices::get(const unsigned int         cell,
                        std::vector<unsigned int> &local) const
  {
    const std::size_t start = std::size_t(cell) * dofs_per_cell;
    AssertIndexRange(start + dofs_per_cell, indices.size() + 1);
    local.assign(indices.begin() + start,
                 indices.begin() + start + dofs_per_cell);
  }
} // namespace RestShape
