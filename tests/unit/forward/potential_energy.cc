// The total potential energy reported with every solve (summary.json
// potential_energy_J, convergence.csv): strain energy + elastic support -
// work of the dead loads + the potential of the follower pressure. Checked
// on the soft cantilever (100 x 10 x 10 mm, E = 100 kPa) bending under
// gravity (tip 50+ mm down), with a follower CSF pressure on its free part
// (held at its edges by the clamp: conservative) and an elastic support:
// - equilibrium is a stationary point: the directional derivative of the
//   energy at the P2 solution (central differences along the solution and
//   along a smooth field) is below 1e-6 of its value at the unloaded state;
// - the energy after solve() is that of the final state, and negative
//   (Newton descends from the unloaded state, energy zero);
// - a rigid rotation of the unloaded body has zero energy, and so has a
//   rest shape w under load at d = w (the work is counted from the rest
//   shape);
// - Galerkin: one global refinement of P1 (nested spaces) lowers it.
// The strain and support energies are computed apart from the forces:
// leaving out the support's energy makes the slopes 0.19 and 0.12 of the
// unloaded ones (tried).
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  std::string
  prm_text(const double gravity, const unsigned int degree, const int level)
  {
    return "subsection Mesh\n set File = meshes/cantilever_tet.msh\n"
           " set Global refinements = " +
           std::to_string(level) +
           "\nend\n"
           "subsection Discretization\n set Polynomial degree = " +
           std::to_string(degree) +
           "\nend\n"
           "subsection Materials\n set Young's modulus = 100000\n"
           " set Poisson's ratio = 0.45\n set Density = 1000\nend\n"
           "subsection Boundary conditions\n set Fixed labels = 2\n"
           " set Elastic support labels = 1\n"
           " set Elastic support stiffness = 100\nend\n"
           "subsection Loads\n set Gravity = 0, 0, " +
           std::to_string(-gravity) +
           "\n set Surface pressure = " + std::to_string(gravity * 10) +
           "\n set Pressure labels = 1\nend\n"
           "subsection Solver\n set Maximum Newton iterations = 200\nend\n";
  }

  /// Energy at the state d + s v (the rest shape and load kept).
  double
  energy_at(ForwardProblem   &f,
            const VectorType &d,
            const VectorType &v,
            const double      s)
  {
    VectorType x = d;
    x.add(s, v);
    f.set_state(x, f.discretization().zero_vector(), f.load());
    f.evaluate();
    return f.potential_energy();
  }

  /// Central difference of the energy at d along v.
  double
  slope(ForwardProblem &f, const VectorType &d, const VectorType &v)
  {
    const double s = 1e-5;
    return (energy_at(f, d, v, s) - energy_at(f, d, v, -s)) / (2 * s);
  }

  /// A smooth field that vanishes at the fixed DoFs.
  VectorType
  smooth_field(const ForwardProblem &f)
  {
    VectorType v = nodal_field(f, [](const Point<3> &X) {
      return Tensor<1, 3>({1e-3 * std::sin(40 * X[0]),
                           2e-3 * std::cos(70 * X[2]),
                           -1e-3 + 3e-3 * X[1]});
    });
    for (const Node &node : f.discretization().owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        if (f.discretization().is_fixed(node.dofs[c]))
          v[node.dofs[c]] = 0;
    v.compress(VectorOperation::insert);
    return v;
  }

  void
  check_stationary(const std::string &name, const double gravity)
  {
    Scene           s(prm_text(gravity, 2, 0));
    ForwardProblem &f = *s.forward;
    const auto      stats =
      f.solve(f.loads().scene_load(), f.discretization().zero_vector());
    if (!stats.converged)
      std::cout << name << ": " << stats.failure << std::endl;
    check_between(name + ": converged", stats.converged, 1, 1);
    const double     reported = f.potential_energy();
    const VectorType d        = f.discretization().owned_copy(f.displacement());
    double           tip_mm   = 0;
    for (const Node &node : f.discretization().owned_nodes())
      tip_mm = std::max(tip_mm, -d[node.dofs[2]] * 1e3);
    std::cout << name << ": tip " << tip_mm << " mm, energy " << reported
              << " J" << std::endl;

    f.evaluate();
    check_below(name + ": energy after solve() is the final state's (rel.)",
                std::abs(f.potential_energy() - reported) / std::abs(reported),
                1e-14);
    const VectorType v  = smooth_field(f);
    const VectorType d0 = f.discretization().zero_vector();
    for (const auto &[direction, field] :
         {std::make_pair(std::string("along the solution"), &d),
          std::make_pair(std::string("along a smooth field"), &v)})
      {
        const double at_solution = slope(f, d, *field);
        const double at_zero     = slope(f, d0, *field);
        std::cout << name << ", " << direction << ": slope " << at_solution
                  << " J at the solution, " << at_zero << " J unloaded"
                  << std::endl;
        check_below(name + ": stationary " + direction +
                      " (slope relative to the unloaded one)",
                    std::abs(at_solution) / std::abs(at_zero),
                    1e-6);
      }
    check_between(name + ": a large-rotation case (tip, mm)", tip_mm, 50, 100);
    // Newton descends from the unloaded state, whose energy is zero.
    check_below(name + ": energy at the solution (J)", reported, -1e-4);
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  check_stationary("P2", 9.81);

  {
    // A rigid rotation of the unloaded body (no support: its springs would
    // resist the motion) stores no energy.
    Scene s("subsection Mesh\n set File = meshes/cantilever_tet.msh\nend\n"
            "subsection Boundary conditions\n set Fixed labels = 2\nend\n");
    ForwardProblem &f = *s.forward;
    const Tensor2   R = rotation(Tensor<1, 3>({0.3, -1.1, 0.7}));
    const Tensor2   I = unit_symmetric_tensor<3>();
    f.set_state(nodal_field(f,
                            [&](const Point<3> &X) {
                              return (R - I) * Tensor<1, 3>(X);
                            }),
                f.discretization().zero_vector(),
                LoadState());
    f.evaluate();
    check_below("rigid rotation of the unloaded body: energy (J)",
                std::abs(f.potential_energy()),
                1e-15);
    // The rest shape under the scene's loads: the work is counted from it.
    const VectorType w = nodal_field(f, [](const Point<3> &X) {
      return Tensor<1, 3>({0.1 * X[2], 0.05 * X[0], 0.2 * X[1]});
    });
    f.set_state(w, w, f.loads().scene_load());
    f.evaluate();
    check_below("a rest shape under load, before it deforms: energy (J)",
                std::abs(f.potential_energy()),
                1e-15);
  }

  {
    // Nested spaces (red refinement of P1): the finer Galerkin solution
    // minimises the same energy over a larger space (P1 locks in bending:
    // the coarse solution is far too stiff).
    double energy[2];
    for (int level = 0; level < 2; ++level)
      {
        Scene           s(prm_text(9.81, 1, level));
        ForwardProblem &f = *s.forward;
        const auto      stats =
          f.solve(f.loads().scene_load(), f.discretization().zero_vector());
        check_between("P1 level " + std::to_string(level) + ": converged",
                      stats.converged,
                      1,
                      1);
        energy[level] = f.potential_energy();
      }
    std::cout << "P1 energy: level 0 " << energy[0] << " J, level 1 "
              << energy[1] << " J" << std::endl;
    check_between("refinement lowers the energy (E1 / E0 - 1, E < 0)",
                  energy[1] / energy[0] - 1,
                  1e-3,
                  10);
  }
  return exit_code();
}
