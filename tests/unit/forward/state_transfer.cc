// StateTransfer (source/state_transfer.cc) carries the displacement and the
// rest displacement from a mesh to its refinement. A field in the finite
// element space of the coarse mesh is also in the space of the refined one,
// so the transfer must reproduce it exactly at every new node:
//
// 1. Q1 hexahedra (the column), refined adaptively with hanging nodes, then
//    refined and coarsened: a trilinear field.
// 2. Q2 hexahedra, refined globally: a triquadratic field.
// 3. P1 and P2 tetrahedra, red-refined (the mesh is rebuilt, children found
//    by their index): a linear and a quadratic field.
//
// Two different fields go through at once (as the displacement and the
// rest displacement do).
// 4. ForwardProblem::solve_from() falls back to loading from zero when
//    Newton fails from its initial guess. Runs on 1 and on 2 MPI ranks (p4est
//    and the fully distributed triangulation; tests/CMakeLists.txt).
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>
#include <restshape/forward/state_transfer.h>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  using Field = std::function<Tensor<1, 3>(const Point<3> &)>;

  /// Largest nodal difference between @p v and @p field, over all ranks.
  double
  max_difference(const ForwardProblem &f,
                 const VectorType     &v,
                 const Field          &field)
  {
    double worst = 0;
    for (const Node &node : f.discretization().owned_nodes())
      {
        const Tensor<1, 3> value = field(node.position);
        for (unsigned int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(v[node.dofs[c]] - value[c]));
      }
    return Utilities::MPI::max(worst, MPI_COMM_WORLD);
  }

  /// Put (u, w) = (first, second) on the scene's mesh, refine it by
  /// @p refine (which gets the callback) and check the transferred fields.
  void
  check_transfer(const std::string                                &name,
                 Scene                                            &s,
                 const Field                                      &first,
                 const Field                                      &second,
                 const std::function<void(std::function<void()>)> &refine,
                 const bool expect_coarsening = false)
  {
    ForwardProblem &f = *s.forward;
    f.set_state(nodal_field(f, first), nodal_field(f, second), LoadState());
    const auto n_before = f.discretization().dof_handler().n_dofs();
    check_below(name + ", before",
                max_difference(f, f.displacement(), first),
                1e-12);

    std::unique_ptr<StateTransfer> transfer;
    unsigned int                   n_coarsened = 0;
    refine([&]() {
      for (const auto &cell : s.mesh->triangulation().active_cell_iterators())
        n_coarsened += cell->is_locally_owned() && cell->coarsen_flag_set();
      transfer = std::make_unique<StateTransfer>(
        f,
        std::vector<const VectorType *>{&f.displacement(),
                                        &f.rest_displacement()});
    });
    f.setup();
    const std::vector<VectorType> out = transfer->interpolate(f);
    std::cout << name << ": " << n_before << " -> "
              << f.discretization().dof_handler().n_dofs() << " DoFs"
              << std::endl;
    check_between(name + ", more DoFs after",
                  f.discretization().dof_handler().n_dofs(),
                  n_before + 1,
                  1e9);
    if (expect_coarsening)
      check_between(name + ", cells coarsened",
                    Utilities::MPI::sum(n_coarsened, MPI_COMM_WORLD),
                    8,
                    1e9);
    check_below(name + ", first field",
                max_difference(f, out[0], first),
                1e-12);
    check_below(name + ", second field",
                max_difference(f, out[1], second),
                1e-12);
  }

  std::string
  scene(const std::string &file, const std::string &cells, const int degree)
  {
    return "subsection Mesh\n set File = " + file +
           "\n set Length unit = mm\n set Cell type = " + cells +
           "\nend\nsubsection Discretization\n set Polynomial degree = " +
           std::to_string(degree) + "\nend\n";
  }

  // Fields of order 1 on the column (coordinates in m, up to 0.05).
  const double s = 1 / 0.05;

  Tensor<1, 3>
  trilinear(const Point<3> &X)
  {
    const double x = s * X[0], y = s * X[1], z = s * X[2];
    return Tensor<1, 3>({1 + x * y * z, x - 2 * y * z, 0.5 + x * y});
  }

  Tensor<1, 3>
  linear(const Point<3> &X)
  {
    const double x = s * X[0], y = s * X[1], z = s * X[2];
    return Tensor<1, 3>({1 + x - y, 2 * z, 0.3 * x + y + z});
  }

  Tensor<1, 3>
  quadratic(const Point<3> &X)
  {
    const double x = s * X[0], y = s * X[1], z = s * X[2];
    return Tensor<1, 3>({x * x - y * z, 1 + x * z, z * z + x * y - y});
  }

  Tensor<1, 3>
  triquadratic(const Point<3> &X)
  {
    const double x = s * X[0], y = s * X[1], z = s * X[2];
    return Tensor<1, 3>({x * x * y * y * z * z, x * y * z * z, 1 - z * z * x});
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  {
    Scene s(scene("meshes/column_hex.msh", "hexahedra", 1));
    // Indicators growing with z (times @p sign): the first refinement
    // refines the top of the column, the second refines the bottom and
    // coarsens the top again.
    const auto marks = [&](const double sign) {
      Vector<float> m(s.mesh->triangulation().n_active_cells());
      for (const auto &cell : s.mesh->triangulation().active_cell_iterators())
        if (cell->is_locally_owned())
          m[cell->active_cell_index()] =
            1 + sign * (cell->center()[2] * 10 + cell->center()[0]);
      return m;
    };
    check_transfer("Q1, adaptive", s, trilinear, linear, [&](auto callback) {
      s.mesh->refine_adaptive(marks(1), 0.3, 0, callback);
    });
    check_transfer(
      "Q1, refined and coarsened",
      s,
      linear,
      trilinear,
      [&](auto callback) {
        s.mesh->refine_adaptive(marks(-1), 0.3, 0.6, callback);
      },
      true);
  }
  {
    Scene s(scene("meshes/column_hex.msh", "hexahedra", 2));
    check_transfer("Q2, global",
                   s,
                   triquadratic,
                   quadratic,
                   [&](auto callback) { s.mesh->refine_global(callback); });
  }
  for (const int degree : {1, 2})
    {
      Scene      s(scene("meshes/column_tet.msh", "tetrahedra", degree));
      const auto field = degree == 1 ? linear : quadratic;
      check_transfer("P" + std::to_string(degree) + ", red refinement",
                     s,
                     field,
                     linear,
                     [&](auto callback) { s.mesh->refine_global(callback); });
    }

  // 4. ForwardProblem::solve_from from a guess that inverts every cell
  // (u = -2 X: F = -I): Newton fails at once, the solve starts again from
  // the unloaded mesh and must end where solve() from there ends.
  {
    Scene                 s(scene("meshes/column_hex.msh", "hexahedra", 1) +
            "subsection Materials\n set Young's modulus = 10000\n set "
                            "Poisson's ratio = 0.3\nend\nsubsection Boundary conditions\n "
                            "set Fixed labels = 2\nend\nsubsection Loads\n set Gravity = 0, "
                            "0, -9.81\nend\n");
    ForwardProblem       &f    = *s.forward;
    const LoadState       load = f.loads().scene_load();
    const SolveStatistics from_zero =
      f.solve(load, f.discretization().zero_vector());
    const VectorType expected = f.discretization().owned_copy(f.displacement());
    const VectorType bad =
      nodal_field(f, [](const Point<3> &X) { return -2 * Tensor<1, 3>(X); });
    const SolveStatistics fallback =
      f.solve_from(&bad, load, f.discretization().zero_vector());
    VectorType difference = f.discretization().owned_copy(f.displacement());
    difference -= expected;
    check_between("solve_from an inverting guess converges",
                  fallback.converged,
                  1,
                  1);
    check_below("  and ends where solve() from zero ends (m)",
                difference.linfty_norm(),
                1e-9 * expected.linfty_norm());
    // The failed attempt stopped at its first assembly, before a step.
    check_between("  with as many Newton steps as solve() from zero",
                  fallback.newton_iterations,
                  from_zero.newton_iterations,
                  from_zero.newton_iterations);
  }
  return exit_code();
}
