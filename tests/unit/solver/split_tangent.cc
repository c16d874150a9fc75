// SplitTangent against the assembled matrix it splits: N (a chain of
// 2-DoF cells) plus rank-one terms k g g^T over 7 DoFs each, with a fixed
// DoF and two DoFs constrained to combinations of others, all put in by
// AffineConstraints::distribute_local_to_global as the assembly does. The
// split's product equals the assembled matrix's, before and after a
// diagonal shift (a Newton step's); W = N + terms entry by entry; CG with
// an AMG built on the split's rows solves as CG and AMG on W do. On 1 and
// on 2 MPI ranks (each its own rows and terms, terms across the ranks'
// border).
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <restshape/solver/split_tangent.h>

#include <cmath>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  constexpr unsigned int n_dofs = 900, term_size = 7;
  using Index = types::global_dof_index;

  struct System
  {
    IndexSet                  owned, relevant;
    AffineConstraints<double> constraints;
    DynamicSparsityPattern    narrow, wide;
  };

  /// Cell i couples DoFs i and i + 1; term t the DoFs 3 t .. 3 t + 6.
  std::vector<Index>
  cell_dofs(const unsigned int i)
  {
    return {i, i + 1};
  }
  std::vector<Index>
  term_dofs(const unsigned int t)
  {
    std::vector<Index> dofs;
    for (unsigned int j = 0; j < term_size; ++j)
      dofs.push_back(3 * t + j);
    return dofs;
  }
  constexpr unsigned int n_cells = n_dofs - 1,
                         n_terms = (n_dofs - term_size) / 3 + 1;

  FullMatrix<double>
  cell_matrix(const unsigned int i)
  {
    const double       k = 1 + 0.3 * std::sin(1. + i);
    FullMatrix<double> m(2, 2);
    m(0, 0) = m(1, 1) = k;
    m(0, 1) = m(1, 0) = -0.9 * k;
    return m;
  }
  double
  term_factor(const unsigned int t)
  {
    return 50 * (1.5 + std::cos(0.7 * t));
  }
  std::vector<double>
  term_gradient(const unsigned int t)
  {
    std::vector<double> g(term_size);
    for (unsigned int j = 0; j < term_size; ++j)
      g[j] = std::sin(1.3 * t + 0.9 * j) + 0.1;
    return g;
  }
  FullMatrix<double>
  outer(const double k, const std::vector<double> &g)
  {
    FullMatrix<double> m(g.size(), g.size());
    for (unsigned int i = 0; i < g.size(); ++i)
      for (unsigned int j = 0; j < g.size(); ++j)
        m(i, j) = k * g[i] * g[j];
    return m;
  }

  System
  make_system()
  {
    System      s;
    const auto  ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const auto  rank  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const Index begin = n_dofs * rank / ranks,
                end   = n_dofs * (rank + 1) / ranks;
    s.owned.set_size(n_dofs);
    s.owned.add_range(begin, end);
    s.relevant = complete_index_set(n_dofs);
    s.constraints.reinit(s.relevant);
    s.constraints.add_line(5); // fixed
    s.constraints.add_line(20);
    s.constraints.add_entry(20, 19, 0.5);
    s.constraints.add_entry(20, 22, 0.25);
    constexpr Index border = n_dofs / 2 + 1; // of the 2 ranks' rows
    s.constraints.add_line(border);
    s.constraints.add_entry(border, border - 2, -0.3);
    s.constraints.add_entry(border, border + 1, 0.7);
    s.constraints.close();
    s.narrow.reinit(n_dofs, n_dofs, s.relevant);
    s.wide.reinit(n_dofs, n_dofs, s.relevant);
    for (unsigned int i = 0; i < n_cells; ++i)
      {
        s.constraints.add_entries_local_to_global(cell_dofs(i), s.narrow, true);
        s.constraints.add_entries_local_to_global(cell_dofs(i), s.wide, true);
      }
    for (unsigned int t = 0; t < n_terms; ++t)
      s.constraints.add_entries_local_to_global(term_dofs(t), s.wide, true);
    for (auto *dsp : {&s.narrow, &s.wide})
      SparsityTools::distribute_sparsity_pattern(*dsp,
                                                 s.owned,
                                                 MPI_COMM_WORLD,
                                                 s.relevant);
    return s;
  }

  /// A cell or term is this rank's if it owns its first DoF.
  bool
  mine(const System &s, const Index first)
  {
    return s.owned.is_element(first);
  }

  VectorType
  test_vector(const System &s)
  {
    VectorType x(s.owned, MPI_COMM_WORLD);
    for (const auto i : s.owned)
      x[i] = std::sin(0.37 * i) + 0.2;
    x.compress(VectorOperation::insert);
    return x;
  }

  double
  difference(const VectorType &a, const VectorType &b)
  {
    VectorType d = a;
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const System                     s = make_system();
  MatrixType                       reference, wide;
  reference.reinit(s.owned, s.owned, s.wide, MPI_COMM_WORLD);
  wide.reinit(s.owned, s.owned, s.wide, MPI_COMM_WORLD);
  SplitTangent split;
  split.reinit(s.owned, s.narrow, MPI_COMM_WORLD);
  split.clear();
  for (unsigned int i = 0; i < n_cells; ++i)
    if (mine(s, i))
      {
        s.constraints.distribute_local_to_global(cell_matrix(i),
                                                 cell_dofs(i),
                                                 reference);
        s.constraints.distribute_local_to_global(cell_matrix(i),
                                                 cell_dofs(i),
                                                 split.narrow());
      }
  for (unsigned int t = 0; t < n_terms; ++t)
    if (mine(s, 3 * t))
      {
        const FullMatrix<double> m = outer(term_factor(t), term_gradient(t));
        s.constraints.distribute_local_to_global(m, term_dofs(t), reference);
        s.constraints.distribute_local_to_global(m, term_dofs(t), wide);
        split.add_term(term_factor(t),
                       term_dofs(t),
                       term_gradient(t),
                       s.constraints);
      }
  reference.compress(VectorOperation::add);
  wide.compress(VectorOperation::add);
  split.finish(wide);
  check_between("the split applies to its matrix", split.applies(wide), 1, 1);
  check_between("... and to no other", split.applies(reference), 0, 0);

  // W = N + terms, entry by entry.
  double worst = 0;
  for (const auto i : s.owned)
    for (auto e = reference.begin(i); e != reference.end(i); ++e)
      worst = std::max(worst,
                       std::abs(e->value() - wide.el(i, e->column())) /
                         reference.diag_element(i));
  check_below("W = N + terms, entry by entry",
              Utilities::MPI::max(worst, MPI_COMM_WORLD),
              1e-14);

  const VectorType x = test_vector(s);
  VectorType       y_reference(x), y_split(x);
  reference.vmult(y_reference, x);
  split.vmult(y_split, x);
  check_below("product, split against assembled",
              difference(y_split, y_reference),
              1e-14);

  // A Newton step's shift of the diagonal, in both matrices.
  for (MatrixType *m : {&reference, &wide})
    {
      for (const auto i : s.owned)
        m->add(i, i, 0.1 * m->diag_element(i));
      m->compress(VectorOperation::add);
    }
  split.refresh_diagonal();
  reference.vmult(y_reference, x);
  split.vmult(y_split, x);
  check_below("product after a diagonal shift",
              difference(y_split, y_reference),
              1e-14);

  // CG with AMG on the split's rows and product against AMG and CG on W.
  const auto solve = [&](const auto &op, const Epetra_RowMatrix &rows) {
    TrilinosWrappers::PreconditionAMG                 amg;
    Teuchos::ParameterList                            list;
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    std::unique_ptr<Epetra_MultiVector>               unused;
    data.set_parameters(list, unused, rows);
    list.set("coarse: max size", 50); // levels, not one direct solve
    amg.initialize(rows, list);
    VectorType           u(x);
    SolverControl        control(200, 1e-12 * x.l2_norm());
    SolverCG<VectorType> cg(control);
    u = 0;
    cg.solve(op, u, x, amg);
    return std::make_pair(u, control.last_step());
  };
  const auto [u_split, its_split] = solve(split, split);
  const auto [u_wide, its_wide] = solve(reference, reference.trilinos_matrix());
  check_below("CG + AMG: solution, split against assembled",
              difference(u_split, u_wide),
              1e-9);
  check_between("CG + AMG: iterations, split against assembled",
                its_split,
                its_wide,
                its_wide);
  check_between("CG + AMG: iterations (AMG more than a direct solve)",
                its_wide,
                3,
                200);
  return exit_code();
}
