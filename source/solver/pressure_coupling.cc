#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <Epetra_CrsMatrix.h>
#include <restshape/base/outer_product.h>
#include <restshape/solver/pressure_coupling.h>

#include <algorithm>
#include <map>

namespace RestShape
{
  using namespace dealii;

  void
  PressureCoupling::clear()
  {
    start = {0};
    columns.clear();
    values.clear();
    factors.clear();
  }

  void
  PressureCoupling::add(const std::vector<types::global_dof_index> &dofs,
                        const double                               *g,
                        const double                                factor,
                        const AffineConstraints<double>            &constraints)
  {
    std::map<types::global_dof_index, double> row;
    for (unsigned int j = 0; j < dofs.size(); ++j)
      {
        if (g[j] == 0)
          continue;
        if (!constraints.is_constrained(dofs[j]))
          row[dofs[j]] += g[j];
        else if (const auto *entries =
                   constraints.get_constraint_entries(dofs[j]))
          for (const auto &[master, weight] : *entries)
            row[master] += weight * g[j];
      }
    for (const auto &[column, value] : row)
      {
        columns.push_back(column);
        values.push_back(value);
      }
    start.push_back(columns.size());
    factors.push_back(factor);
  }

  void
  PressureCoupling::finish(const IndexSet &owned_dofs,
                           const MPI_Comm  communicator)
  {
    const types::global_dof_index n_own = factors.size();
    const IndexSet own = dealii::Utilities::MPI::create_ascending_partitioning(
      communicator,
      n_own)[dealii::Utilities::MPI::this_mpi_process(communicator)];
    n_total = own.size();
    first   = n_own > 0 ? own.nth_index_in_set(0) : 0;

    DynamicSparsityPattern pattern(n_total, owned_dofs.size(), own);
    for (types::global_dof_index i = 0; i < n_own; ++i)
      pattern.add_entries(first + i,
                          columns.begin() + start[i],
                          columns.begin() + start[i + 1],
                          true);
    G.reinit(own, owned_dofs, pattern, communicator);
    G_squared.reinit(own, owned_dofs, pattern, communicator);
    std::vector<double> squares;
    for (types::global_dof_index i = 0; i < n_own; ++i)
      {
        const auto n = static_cast<unsigned int>(start[i + 1] - start[i]);
        G.set(first + i, n, &columns[start[i]], &values[start[i]], false);
        squares.assign(values.begin() + start[i],
                       values.begin() + start[i + 1]);
        for (double &s : squares)
          s *= s;
        G_squared.set(first + i, n, &columns[start[i]], squares.data(), false);
      }
    G.compress(VectorOperation::insert);
    G_squared.compress(VectorOperation::insert);
  }

  void
  PressureCoupling::displacement_block(const MatrixType &K, MatrixType &A) const
  {
    A.copy_from(K);
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  g;
    for (std::size_t i = 0; i < factors.size(); ++i)
      {
        dofs.assign(columns.begin() + start[i], columns.begin() + start[i + 1]);
        g.assign(values.begin() + start[i], values.begin() + start[i + 1]);
        add_outer_product(-factors[i], dofs, g, A);
      }
    A.compress(VectorOperation::add);
  }

  VectorType
  PressureCoupling::inverse_schur_diagonal(const VectorType &A_diagonal) const
  {
    VectorType inverse_diagonal(A_diagonal);
    for (const auto j : A_diagonal.locally_owned_elements())
      inverse_diagonal[j] = A_diagonal[j] > 0 ? 1. / A_diagonal[j] : 0.;
    inverse_diagonal.compress(VectorOperation::insert);
    VectorType schur(G.locally_owned_range_indices(), G.get_mpi_communicator());
    G_squared.vmult(schur, inverse_diagonal);
    schur *= schur_safety;
    for (std::size_t i = 0; i < factors.size(); ++i)
      {
        const auto row = first + i;
        schur[row]     = 1. / (schur[row] + 1. / factors[i]);
      }
    schur.compress(VectorOperation::insert);
    return schur;
  }
} // namespace RestShape
