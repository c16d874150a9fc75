// TangentScatter and ConstraintLookup against what they replace,
// AffineConstraints::distribute_local_to_global: a P2 vector element on a
// tetrahedral mesh whose DoFs are free, fixed at zero, fixed at a value
// (a contact node's gap) or linked to others (a sliding direction), cell
// matrices and vectors of made-up numbers added twice (the first time the
// positions are found, then they are used). The matrices and vectors must
// be the same to the last bit, and each path must have been taken.
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <restshape/fem/tangent_scatter.h>

#include <cmath>
#include <iostream>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  using Buffer = LinearAlgebra::distributed::Vector<double>;

  /// A made-up, non-symmetric cell matrix and vector, by cell and pass.
  void
  cell_numbers(const unsigned int  cell,
               const unsigned int  pass,
               FullMatrix<double> &matrix,
               Vector<double>     &vector)
  {
    for (unsigned int i = 0; i < matrix.m(); ++i)
      {
        vector(i) = std::sin(1.0 + cell + 0.37 * i + pass);
        for (unsigned int j = 0; j < matrix.n(); ++j)
          matrix(i, j) = std::cos(0.1 * cell + 0.7 * i + 0.3 * j + pass) +
                         (i == j ? 3. : 0.);
      }
  }

  /// Zero, a value or a link, by the DoF's support point.
  AffineConstraints<double>
  make_constraints(const DoFHandler<3> &dof_handler)
  {
    AffineConstraints<double> constraints;
    const IndexSet            all = complete_index_set(dof_handler.n_dofs());
    constraints.reinit(all);
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        const Point<3> x = cell->center();
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const types::global_dof_index dof = dofs[i];
            if (constraints.is_constrained(dof))
              continue;
            if (x[0] < 0.2 && i % 2 == 0)
              constraints.add_line(dof); // a fixed label
            else if (x[0] > 0.8 && i % 3 == 0)
              {
                constraints.add_line(dof); // a contact node's gap
                constraints.set_inhomogeneity(dof, 0.01 * (1 + dof % 5));
              }
            else if (x[1] > 0.8 && i % 5 == 1 && dof > 0 &&
                     !constraints.is_constrained(dof - 1))
              {
                constraints.add_line(dof); // a sliding direction
                constraints.add_entry(dof, dof - 1, 0.5);
              }
          }
      }
    constraints.close();
    return constraints;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Triangulation<3>                 hexahedra, mesh;
  GridGenerator::subdivided_hyper_cube(hexahedra, 3);
  GridGenerator::convert_hypercube_to_simplex_mesh(hexahedra, mesh);
  const FESystem<3> fe(FE_SimplexP<3>(2), 3);
  DoFHandler<3>     dof_handler(mesh);
  dof_handler.distribute_dofs(fe);
  const AffineConstraints<double> constraints = make_constraints(dof_handler);
  const IndexSet all = complete_index_set(dof_handler.n_dofs());

  DynamicSparsityPattern dsp(dof_handler.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, true);
  TrilinosWrappers::SparseMatrix reference, scattered;
  reference.reinit(all, all, dsp, MPI_COMM_WORLD);
  scattered.reinit(all, all, dsp, MPI_COMM_WORLD);
  Buffer reference_rhs(all, all, MPI_COMM_WORLD), rhs(reference_rhs),
    reference_vector(reference_rhs), vector(reference_rhs);

  ConstraintLookup lookup;
  lookup.reinit(constraints, *rhs.get_partitioner());
  TangentScatter                       scatter;
  const unsigned int                   n = fe.n_dofs_per_cell();
  FullMatrix<double>                   cell_matrix(n, n);
  Vector<double>                       cell_vector(n);
  std::vector<types::global_dof_index> dofs(n);
  std::vector<unsigned int>            local(n);
  unsigned int                         cells_of[3] = {0, 0, 0};
  for (unsigned int pass = 0; pass < 2; ++pass)
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          local[i] = rhs.get_partitioner()->global_to_local(dofs[i]);
        cell_numbers(cell->active_cell_index(), pass, cell_matrix, cell_vector);
        constraints.distribute_local_to_global(
          cell_matrix, cell_vector, dofs, reference, reference_rhs);
        scatter.add(cell->active_cell_index(),
                    lookup,
                    local,
                    cell_matrix,
                    cell_vector,
                    dofs,
                    scattered,
                    rhs);
        constraints.distribute_local_to_global(cell_vector,
                                               dofs,
                                               reference_vector);
        lookup.distribute(cell_vector, dofs, local, vector);
        ++cells_of[static_cast<int>(lookup.strongest(local))];
      }
  reference.compress(VectorOperation::add);
  scattered.compress(VectorOperation::add);

  double matrix_difference = 0, largest = 0;
  for (auto entry = reference.begin(); entry != reference.end(); ++entry)
    {
      matrix_difference =
        std::max(matrix_difference,
                 std::abs(entry->value() -
                          scattered.el(entry->row(), entry->column())));
      largest = std::max(largest, std::abs(entry->value()));
    }
  double rhs_difference = 0, vector_difference = 0;
  for (types::global_dof_index i = 0; i < rhs.size(); ++i)
    {
      rhs_difference =
        std::max(rhs_difference, std::abs(rhs(i) - reference_rhs(i)));
      vector_difference =
        std::max(vector_difference, std::abs(vector(i) - reference_vector(i)));
    }
  std::cout << "cells free / with fixed DoFs / with linked DoFs: "
            << cells_of[0] / 2 << " / " << cells_of[1] / 2 << " / "
            << cells_of[2] / 2 << "; constraints "
            << constraints.n_constraints() << std::endl;
  check_below("matrix, |difference|", matrix_difference, 0);
  check_below("right-hand side, |difference|", rhs_difference, 0);
  check_below("cell vectors, |difference|", vector_difference, 0);
  check_below("entries > 1 (a test of something)", -largest, -1);
  for (const unsigned int count : cells_of)
    check_below("cells of each kind (a test of every path)",
                -double(count),
                -1);
  return exit_code();
}
