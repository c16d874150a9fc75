// Surface loads (Loads/Pressure load, Fluid load) on a polyhedral ball of
// P1 tetrahedra (radius 50 mm, E = 10 kPa, nu = 0.3):
// - inflated by a follower suction p = -3 kPa, the ball's exact
//   large-deformation state of the co-rotational law is the homogeneous
//   stretch lambda with 3 K (lambda - 1) / lambda^2 = -p (the Cauchy stress
//   balances p on the current surface): the residual vanishes there, and
//   not at the dead load's lambda = 1 - p / (3 K), where the dead load's
//   does;
// - fully immersed in a hydrostatic fluid (level 50 mm above its top) the
//   ball receives exactly its buoyancy rho_f |g| V, also after the stretch
//   (V then the current volume), whatever the uniform pressure on top;
// - the tangent matches central differences of the residual at a rotated
//   and sheared state, on the closed surface (symmetric) and on an open
//   one with free edges (the pressure on half of the ball: non-symmetric).
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>

#include <restshape/base/mpi_start.h>
#include <restshape/forward/forward_results.h>
#include <restshape/loads/surface_load.h>
#include <unistd.h>

#include <filesystem>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  const double radius = 0.05, E = 1e4, nu = 0.3, rho_fluid = 1000;

  /// The ball as a gmsh file (mm): label 1, or labels 1 (x > 0) and 2.
  std::string
  write_ball(const bool two_labels)
  {
    Triangulation<3> hexes, tets;
    GridGenerator::hyper_ball(hexes, Point<3>(), radius);
    hexes.refine_global(1);
    GridGenerator::convert_hypercube_to_simplex_mesh(hexes, tets);
    MeshDescription mesh;
    mesh.vertices = tets.get_vertices();
    for (const auto &cell : tets.active_cell_iterators())
      {
        CellData<3> c(4);
        for (unsigned int v = 0; v < 4; ++v)
          c.vertices[v] = cell->vertex_index(v);
        c.material_id = (two_labels && cell->center()[0] < 0) ? 2 : 1;
        mesh.cells.push_back(c);
      }
    const std::string file = (std::filesystem::temp_directory_path() /
                              ("restshape_ball_" + std::to_string(getpid()) +
                               (two_labels ? "_2" : "_1") + ".msh"))
                               .string();
    write_gmsh(mesh, 1e-3, file);
    return file;
  }

  std::string
  prm_text(const std::string &mesh,
           const std::string &loads,
           const std::string &pressure_labels = "",
           const std::string &gravity         = "0, 0, 0")
  {
    return "subsection Mesh\n set File = " + mesh +
           "\nend\n"
           "subsection Discretization\n set Polynomial degree = 1\n"
           " set Tangent = consistent\nend\n"
           "subsection Materials\n set Young's modulus = " +
           std::to_string(E) +
           "\n set Poisson's ratio = " + std::to_string(nu) +
           "\n set Density = 1000\nend\n"
           "subsection Boundary conditions\n set Fixed labels =\nend\n"
           "subsection Loads\n set Gravity = " +
           gravity + "\n" + loads +
           " set Pressure labels = " + pressure_labels + "\nend\n";
  }

  /// The largest nodal residual over the largest nodal external force.
  double
  relative_residual(ForwardProblem &f, const double lambda, const double p)
  {
    const VectorType d = nodal_field(f, [&](const Point<3> &X) {
      return Tensor<1, 3>((lambda - 1) * X);
    });
    LoadState        load;
    load.set(SurfaceLoad::pressure_name, {{{p}, 1.}});
    f.set_state(d, f.discretization().zero_vector(), load);
    f.evaluate();
    // The external force of a node is about p times its area: compare with
    // the pressure's force on the whole ball over the number of nodes.
    const double area_per_node = 4 * M_PI * radius * radius * lambda * lambda /
                                 (f.discretization().owned_nodes().size() / 3.);
    return f.raw_residual().linfty_norm() / (std::abs(p) * area_per_node);
  }

  void
  check_inflation(const std::string &mesh)
  {
    const double p = -3000, K = E / (3 * (1 - 2 * nu));
    // 3 K (l - 1) = -p l^2: the root near 1.
    const double follower =
                   (3 * K - std::sqrt(9 * K * K + 12 * K * p)) / (-2 * p),
                 dead = 1 - p / (3 * K);
    std::cout << "stretch: follower " << follower << ", dead " << dead
              << std::endl;
    Scene f_scene(prm_text(mesh, " set Surface pressure = -3000\n"));
    check_below("follower suction: residual at the exact stretch",
                relative_residual(*f_scene.forward, follower, p),
                1e-10);
    check_between("follower suction: residual at the dead load's stretch",
                  relative_residual(*f_scene.forward, dead, p),
                  1e-3,
                  1e3);
    Scene d_scene(prm_text(mesh,
                           " set Surface pressure = -3000\n"
                           " set Pressure load = dead\n"));
    check_below("dead suction: residual at its stretch",
                relative_residual(*d_scene.forward, dead, p),
                1e-10);
  }

  void
  check_buoyancy(const std::string &mesh)
  {
    Scene           s(prm_text(mesh,
                     " set Surface pressure = 250\n"
                               " set Fluid density = 1000\n"
                               " set Fluid load = hydrostatic pressure\n"
                               " set Fluid level = 0, 0, 100\n",
                     "",
                     "0, 0, -9.81"));
    ForwardProblem &f = *s.forward;
    // The mesh volume (polyhedral ball).
    double volume = 0;
    for (const auto &cell : s.mesh->triangulation().active_cell_iterators())
      volume += cell->measure();
    for (const double lambda : {1., 1.1})
      {
        const VectorType d = nodal_field(f, [&](const Point<3> &X) {
          return Tensor<1, 3>((lambda - 1) * X);
        });
        // Gravity (0, 0, -9.81) and the fluid's column (Loads).
        LoadState load = f.loads().scene_load();
        load.set(SurfaceLoad::pressure_name, {{{250.}, 1.}});
        f.set_state(d, f.discretization().zero_vector(), load);
        const Tensor<1, 3> force = surface_force(f, load);
        const double expected = rho_fluid * 9.81 * volume * std::pow(lambda, 3);
        std::cout << "stretch " << lambda << ": surface force " << force
                  << " N, buoyancy " << expected << " N" << std::endl;
        check_below("immersed ball, stretch " + std::to_string(lambda) +
                      ": surface force against Archimedes (rel.)",
                    (force - Tensor<1, 3>({0, 0, expected})).norm() / expected,
                    1e-10);
      }
  }

  /// |K v - (R(d - e v) - R(d + e v)) / 2e| / |K v| at a rotated and
  /// sheared state.
  double
  tangent_error(ForwardProblem &f)
  {
    const Tensor2    Q = rotation(Tensor<1, 3>({0.3, -0.5, 0.2}));
    const VectorType d = nodal_field(f, [&](const Point<3> &X) {
      const Tensor<1, 3> sheared({X[0] + 0.2 * X[1], X[1], X[2] - 0.1 * X[0]});
      return Tensor<1, 3>(Q * sheared - X);
    });
    const VectorType v = nodal_field(f, [](const Point<3> &X) {
      return Tensor<1, 3>(
        {std::sin(60 * X[1]) * 1e-3, std::cos(40 * X[2]) * 1e-3, X[0] * 0.02});
    });
    LoadState load = f.loads().scene_load(); // gravity (0, 0, -9.81), the fluid
    load.set(SurfaceLoad::pressure_name, {{{400.}, 1.}});
    const auto residual_at = [&](const double s) {
      VectorType x = d;
      x.add(s, v);
      f.set_state(x, f.discretization().zero_vector(), load);
      f.evaluate();
      return f.discretization().owned_copy(f.raw_residual());
    };
    const double e  = 1e-6;
    VectorType   fd = residual_at(-e);
    fd -= residual_at(e);
    fd /= 2 * e;
    f.set_state(d, f.discretization().zero_vector(), load);
    f.evaluate(true);
    VectorType Kv = f.discretization().zero_vector();
    f.tangent_matrix().vmult(Kv, v);
    const double norm = Kv.l2_norm();
    Kv -= fd;
    return Kv.l2_norm() / norm;
  }

  void
  check_tangent(const std::string &mesh,
                const std::string &labels,
                const bool         symmetric)
  {
    // The fluid level above the ball: every face wetted (p smooth).
    Scene             s(prm_text(mesh,
                     " set Surface pressure = 400\n"
                                 " set Fluid density = 1000\n"
                                 " set Fluid load = hydrostatic pressure\n"
                                 " set Fluid level = 0, 0, 60\n",
                     labels));
    const std::string name =
      labels.empty() ? "closed surface" : "open surface, free edges";
    check_between(name + ": tangent symmetric",
                  s.forward->loads().symmetric(),
                  symmetric,
                  symmetric);
    check_below(name + ": tangent against central differences (rel.)",
                tangent_error(*s.forward),
                1e-6);
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string one = write_ball(false), two = write_ball(true);
  check_inflation(one);
  check_buoyancy(one);
  check_tangent(one, "", true);
  check_tangent(two, "1", false);
  std::filesystem::remove(one);
  std::filesystem::remove(two);
  return exit_code();
}
