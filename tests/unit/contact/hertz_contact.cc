// Hertz contact: an elastic hemisphere (R = 50 mm, E = 10 kPa, nu = 0.3),
// dome down, pressed onto a rigid plane by a uniform pressure on its flat
// top (15 Pa, top nodes held laterally). Hertz, rigid plane, E* = E/(1-nu^2):
//     a = (3 F R / (4 E*))^(1/3),   p0 = 3 F / (2 pi a^2),
// with F the contact force (= the applied force). Here a/R ~ 0.14: the small
// strain range. Q2 hexahedra on meshes graded towards the pole, refined once:
// the contact radius (largest radius of an active node) and the peak
// pressure must approach Hertz, and on the finer mesh agree within 3 %
// (radius) and 3 % (peak pressure), 25 % for the peak on the coarse mesh.
// The contact force must balance the load, and no active node may pull with
// more than the accepted 0.1 % of it.
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>
#include <restshape/contact/contact.h>
#include <restshape/contact/contact_report.h>
#include <restshape/forward/forward_results.h>
#include <restshape/mesh/generated_meshes.h>
#include <restshape/mesh/gmsh_io.h>

#include <filesystem>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  struct Result
  {
    double       force, load, a_num, a_hertz, p_num, p_hertz, pull;
    unsigned int newton;
  };

  Result
  solve(const unsigned int refinements)
  {
    const std::string file = std::filesystem::temp_directory_path().string() +
                             "/restshape_hemisphere_" +
                             std::to_string(refinements) + ".msh";
    {
      Triangulation<3> tria;
      make_hemisphere(tria, 50, refinements, 2);
      write_gmsh(
        tria, [&](unsigned int v) { return tria.get_vertices()[v]; }, 1., file);
    }
    Scene s(
      "subsection Mesh\n set File = " + file +
      "\n set Cell type = hexahedra\nend\n"
      "subsection Discretization\n set Polynomial degree = 2\nend\n"
      "subsection Materials\n set Young's modulus = 10000\n set Poisson's ratio = 0.3\n"
      " set Density = 0\nend\n"
      "subsection Boundary conditions\n set Fixed labels = 2:xy\nend\n"
      "subsection Loads\n set Surface pressure = 15\n set Pressure labels = 2\nend\n"
      "subsection Contact\n set Obstacle file = meshes/floor_large.off\n set Side = outside\nend\n"
      // No fixed label holds z, so auto would take the direct solver: 13 s
      // a solve on the fine mesh's 77,763 DoFs, against 2 s with GMRES + AMG
      // (the follower pressure's tangent is not symmetric), which solves
      // the same contact problem (245 active nodes, the same force).
      "subsection Solver\n set Linear solver = cg-amg\nend\n");
    ContactProblem       &contact = s.add_contact();
    const SolveStatistics stats =
      s.forward->solve(s.forward->loads().scene_load(),
                       s.forward->discretization().zero_vector());
    std::filesystem::remove(file);
    if (!stats.converged)
      std::cout << "refinements " << refinements
                << ": not converged: " << stats.failure << std::endl;

    Result r;
    r.newton = stats.converged ? stats.newton_iterations : 0;
    r.force  = ContactReport(contact).total_force(s.forward->raw_residual())[2];
    r.load   = -total_external_force(*s.forward, s.forward->load())[2];
    const double E = 1e4 / (1 - 0.3 * 0.3), R = 0.05;
    r.a_hertz = std::cbrt(3 * r.force * R / (4 * E));
    r.p_hertz = 3 * r.force / (2 * numbers::PI * r.a_hertz * r.a_hertz);
    r.a_num   = ContactReport(contact).contact_radius(Point<3>(),
                                                    Tensor<1, 3>({0, 0, 1}));
    r.p_num =
      ContactReport(contact).pressure_range(s.forward->raw_residual()).second;
    r.pull =
      ContactReport(contact).adhesion(s.forward->raw_residual()).fraction;
    std::cout << "refinements " << refinements << ": "
              << s.forward->discretization().dof_handler().n_dofs() << " DoFs, "
              << ContactReport(contact).n_active() << " active nodes, "
              << r.newton << " Newton iterations; F = " << r.force
              << " N; a = " << r.a_num * 1e3 << " mm (Hertz " << r.a_hertz * 1e3
              << "), p0 = " << r.p_num << " Pa (Hertz " << r.p_hertz
              << "); pull of active nodes " << r.pull << " of F" << std::endl;
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Result                     coarse = solve(2);
  const Result                     fine   = solve(3);
  for (const Result &r : {coarse, fine})
    {
      check_between("converged", r.newton > 0, 1, 1);
      check_below("contact force vs applied load (relative)",
                  std::abs(r.force - r.load) / r.load,
                  1e-8);
      check_below("pull of active nodes over the contact force", r.pull, 1e-3);
    }
  const auto err_a = [](const Result &r) {
    return std::abs(r.a_num - r.a_hertz) / r.a_hertz;
  };
  const auto err_p = [](const Result &r) {
    return std::abs(r.p_num - r.p_hertz) / r.p_hertz;
  };
  check_below("fine mesh: contact radius vs Hertz (relative)",
              err_a(fine),
              0.03);
  check_below("fine mesh: peak pressure vs Hertz (relative)",
              err_p(fine),
              0.03);
  check_below("coarse mesh: peak pressure vs Hertz (relative)",
              err_p(coarse),
              0.25);
  check_below("peak pressure error decreases under refinement (fine/coarse)",
              err_p(fine) / err_p(coarse),
              0.5);
  return exit_code();
}
