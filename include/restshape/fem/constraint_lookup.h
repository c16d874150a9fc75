// Which DoFs one AffineConstraints constrains, and how, by the local index
// of the assembly's distributed vectors: free, fixed (a value, no other
// DoF: a fixed label, a contact node's normal) or linked to other DoFs
// (hanging nodes, sliding directions). Built once per assembly from the
// constraint lines, it answers for a cell's DoFs with an array load where
// AffineConstraints::is_constrained() searches an IndexSet per DoF (a
// profile of the P1 brain assembly: 2,000 instructions per cell for the
// three cell vectors alone). distribute() adds a cell vector as
// distribute_local_to_global does, the same numbers in the same order.
#ifndef restshape_fem_constraint_lookup_h
#define restshape_fem_constraint_lookup_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

#include <cstdint>
#include <vector>

namespace RestShape
{
  class ConstraintLookup
  {
  public:
    enum class Kind : std::uint8_t
    {
      free,
      fixed, // a value only (no entries), possibly inhomogeneous
      linked // entries: a combination of other DoFs
    };
    using Buffer = dealii::LinearAlgebra::distributed::Vector<double>;

    /// Take the lines of @p constraints (closed), for vectors of
    /// @p partitioner; lines of DoFs it does not hold are left out.
    void
    reinit(const dealii::AffineConstraints<double>   &constraints,
           const dealii::Utilities::MPI::Partitioner &partitioner);

    Kind
    kind(const unsigned int local_index) const
    {
      return kinds[local_index];
    }
    double
    inhomogeneity(const unsigned int local_index) const
    {
      return inhomogeneities[local_index];
    }
    /// The most constrained kind among the DoFs @p local (local indices).
    Kind
    strongest(const std::vector<unsigned int> &local) const;

    /// global += the cell vector @p cell at the cell's DoFs @p dofs (local
    /// indices @p local), as distribute_local_to_global() adds it.
    void
    distribute(const dealii::Vector<double>                       &cell,
               const std::vector<dealii::types::global_dof_index> &dofs,
               const std::vector<unsigned int>                    &local,
               Buffer &global) const;

    /// The constraints the lookup was built from.
    const dealii::AffineConstraints<double> &
    constraints() const
    {
      return *source;
    }

  private:
    const dealii::AffineConstraints<double> *source = nullptr;
    std::vector<Kind>                        kinds;
    std::vector<double>                      inhomogeneities;
    std::vector<unsigned int>                marked; // local indices not free
  };
} // namespace RestShape

#endif
