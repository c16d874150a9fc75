#include <restshape/fem/constraint_lookup.h>

#include <algorithm>

namespace RestShape
{
  using namespace dealii;

  void
  ConstraintLookup::reinit(const AffineConstraints<double>   &constraints,
                           const Utilities::MPI::Partitioner &partitioner)
  {
    source = &constraints;
    const std::size_t size =
      partitioner.locally_owned_size() + partitioner.n_ghost_indices();
    if (kinds.size() != size)
      {
        kinds.assign(size, Kind::free);
        inhomogeneities.assign(size, 0.);
        marked.clear();
      }
    for (const unsigned int i : marked)
      {
        kinds[i]           = Kind::free;
        inhomogeneities[i] = 0.;
      }
    marked.clear();
    for (const auto &line : constraints.get_lines())
      {
        if (!partitioner.in_local_range(line.index) &&
            !partitioner.is_ghost_entry(line.index))
          continue;
        const unsigned int i = partitioner.global_to_local(line.index);
        kinds[i]           = line.entries.empty() ? Kind::fixed : Kind::linked;
        inhomogeneities[i] = line.inhomogeneity;
        marked.push_back(i);
      }
  }

  ConstraintLookup::Kind
  ConstraintLookup::strongest(const std::vector<unsigned int> &local) const
  {
    // The kinds are 0, 1 and 2: their maximum from their bitwise or.
    static_assert(static_cast<int>(Kind::free) == 0 &&
                  static_cast<int>(Kind::fixed) == 1 &&
                  static_cast<int>(Kind::linked) == 2);
    unsigned int any = 0;
    for (const unsigned int i : local)
      any |= static_cast<unsigned int>(kinds[i]);
    return (any & 2) != 0 ? Kind::linked : static_cast<Kind>(any);
  }

  void
  ConstraintLookup::distribute(const Vector<double>                       &cell,
                               const std::vector<types::global_dof_index> &dofs,
                               const std::vector<unsigned int> &local,
                               Buffer                          &global) const
  {
    const Kind kind = strongest(local);
    if (kind == Kind::linked)
      {
        source->distribute_local_to_global(cell, dofs, global);
        return;
      }
    if (kind == Kind::free)
      {
        for (unsigned int i = 0; i < local.size(); ++i)
          global.local_element(local[i]) += cell(i);
        return;
      }
    // A fixed DoF takes nothing from a cell vector.
    for (unsigned int i = 0; i < local.size(); ++i)
      if (kinds[local[i]] == Kind::free)
        global.local_element(local[i]) += cell(i);
  }
} // namespace RestShape
