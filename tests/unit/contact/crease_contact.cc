// Contact in the creases of a triangulated obstacle: an elastic hemisphere
// (R = 50 mm, E = 10 kPa, nu = 0.3), dome down, its flat top fixed, sags
// under gravity (x 5) into a rigid bowl: a closed icosphere of 320 flat
// faces, circumradius 52 mm, centred on the hemisphere's centre (Side =
// inside, as a brain in a skull). From inside, every edge of the bowl is a
// crease where two faces meet at about 12 degrees, and the dome presses
// into them. Nodes in a crease hold both faces' planes; before they did,
// the closest face alternated, the normal was fixed to a smoothed one and
// the gaps converged linearly. Held and fixed planes help Newton on the
// way; the converged state must meet the contact conditions against the
// bowl itself (the strict check releases planes a node has left, so the
// final state may hold none). Checks: the solve converges, the strict
// contact conditions hold (no node through the bowl, every active node on
// it and pushing), fixing the planes at their first change does not change
// the sag, no active node pulls with more than 0.1 % of the contact force,
// and the forces balance (weight = contact force + reaction at the fixed
// top, each component, relative to the weight).
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>
#include <restshape/contact/contact.h>
#include <restshape/contact/contact_report.h>
#include <restshape/forward/forward_results.h>
#include <restshape/mesh/generated_meshes.h>
#include <restshape/mesh/gmsh_io.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  /// An icosphere (icosahedron split twice: 320 faces) of circumradius
  /// @p radius around @p centre, faces oriented outward, as OFF.
  void
  write_icosphere(const std::string &file,
                  const Point<3>    &centre,
                  const double       radius)
  {
    const double                             t = (1 + std::sqrt(5.)) / 2;
    std::vector<Point<3>>                    v = {{-1, t, 0},
                                                  {1, t, 0},
                                                  {-1, -t, 0},
                                                  {1, -t, 0},
                                                  {0, -1, t},
                                                  {0, 1, t},
                                                  {0, -1, -t},
                                                  {0, 1, -t},
                                                  {t, 0, -1},
                                                  {t, 0, 1},
                                                  {-t, 0, -1},
                                                  {-t, 0, 1}};
    std::vector<std::array<unsigned int, 3>> f = {
      {{0, 11, 5}}, {{0, 5, 1}},  {{0, 1, 7}},   {{0, 7, 10}}, {{0, 10, 11}},
      {{1, 5, 9}},  {{5, 11, 4}}, {{11, 10, 2}}, {{10, 7, 6}}, {{7, 1, 8}},
      {{3, 9, 4}},  {{3, 4, 2}},  {{3, 2, 6}},   {{3, 6, 8}},  {{3, 8, 9}},
      {{4, 9, 5}},  {{2, 4, 11}}, {{6, 2, 10}},  {{8, 6, 7}},  {{9, 8, 1}}};
    for (Point<3> &p : v)
      p /= p.norm();
    for (unsigned int level = 0; level < 2; ++level)
      {
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> middle;
        const auto mid = [&](unsigned int a, unsigned int b) {
          const auto key = std::minmax(a, b);
          auto       it  = middle.find(key);
          if (it != middle.end())
            return it->second;
          Point<3> m = v[a] + v[b];
          v.push_back(m / m.norm());
          return middle[key] = v.size() - 1;
        };
        std::vector<std::array<unsigned int, 3>> finer;
        for (const auto &[a, b, c] : f)
          {
            const unsigned int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            finer.push_back({{a, ab, ca}});
            finer.push_back({{b, bc, ab}});
            finer.push_back({{c, ca, bc}});
            finer.push_back({{ab, bc, ca}});
          }
        f = finer;
      }
    std::ofstream out(file);
    out << "OFF\n" << v.size() << ' ' << f.size() << " 0\n";
    for (const Point<3> &p : v)
      out << centre + radius * p << '\n';
    for (auto [a, b, c] : f)
      {
        // Outward: the normal points away from the centre.
        if (cross_product_3d(v[b] - v[a], v[c] - v[a]) * (v[a] + v[b] + v[c]) <
            0)
          std::swap(b, c);
        out << "3 " << a << ' ' << b << ' ' << c << '\n';
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string dir       = std::filesystem::temp_directory_path().string();
  const std::string mesh_file = dir + "/restshape_crease_hemisphere.msh";
  const std::string bowl_file = dir + "/restshape_crease_bowl.off";
  {
    Triangulation<3> tria;
    make_hemisphere(tria, 50, 2, 2);
    write_gmsh(
      tria,
      [&](unsigned int v) { return tria.get_vertices()[v]; },
      1.,
      mesh_file);
  }
  write_icosphere(bowl_file, Point<3>(0, 0, 50), 51);

  // The default, and the planes fixed at their first change (Contact/
  // Crease plane changes = 0): the fixed planes are exact linear
  // constraints; the nodes on them may end slightly off the bowl.
  double sag[2];
  for (const unsigned int changes : {6u, 0u})
    {
      Scene                 s("subsection Mesh\n set File = " + mesh_file +
              "\n set Cell type = hexahedra\nend\n"
                              "subsection Materials\n set Young's modulus = 10000\n"
                              " set Poisson's ratio = 0.3\n set Density = 1000\nend\n"
                              "subsection Boundary conditions\n set Fixed labels = "
                              "2\nend\n"
                              "subsection Loads\n set Gravity = 0, 0, -98.1\nend\n"
                              "subsection Contact\n set Obstacle file = " +
              bowl_file + "\n set Side = inside\n set Crease plane changes = " +
              std::to_string(changes) + "\nend\n");
      ContactProblem       &contact = s.add_contact();
      const SolveStatistics stats =
        s.forward->solve(s.forward->loads().scene_load(),
                         s.forward->discretization().zero_vector());

      const Tensor<1, 3> weight =
        total_external_force(*s.forward, s.forward->load());
      const Tensor<1, 3> balance =
        weight + ContactReport(contact).total_force(s.forward->raw_residual()) +
        support_reaction(*s.forward);
      const auto [n_fixed, distance] =
        ContactReport(contact).fixed_plane_nodes();
      sag[changes == 0] =
        nodal_norms(s.forward->discretization(), s.forward->displacement())
          .second;
      const std::string tag =
        " (Crease plane changes = " + std::to_string(changes) + ")";
      std::cout << "Crease plane changes = " << changes << ": "
                << s.forward->discretization().dof_handler().n_dofs()
                << " DoFs ("
                << s.forward->discretization().locally_owned_dofs().n_elements()
                << " on this of "
                << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
                << " ranks), " << ContactReport(contact).n_active()
                << " active nodes, " << ContactReport(contact).n_held()
                << " in creases, " << n_fixed << " on fixed planes (up to "
                << distance * 1e3 << " mm off the bowl), "
                << stats.newton_iterations << " Newton iterations, "
                << stats.load_steps << " load steps, sag "
                << sag[changes == 0] * 1e3 << " mm, energy "
                << s.forward->potential_energy() << " J"
                << (stats.converged ? "" : ": " + stats.failure) << std::endl;
      check_between("converged" + tag, stats.converged, 1, 1);
      const ContactConditions conditions =
        contact.check_conditions(s.forward->displacement(),
                                 s.forward->raw_residual(),
                                 1e-8 * weight.norm());
      std::cout << "  " << conditions.text() << std::endl;
      check_between("strict contact conditions hold" + tag,
                    conditions.satisfied(),
                    1,
                    1);
      check_below("distance of fixed-plane nodes off the bowl (mm)" + tag,
                  distance * 1e3,
                  0.05);
      const ContactReport::Adhesion adhesion =
        ContactReport(contact).adhesion(s.forward->raw_residual());
      std::cout << "  " << adhesion.nodes << " active nodes pull, with "
                << adhesion.fraction << " of the contact force" << std::endl;
      check_below("pull of active nodes over the contact force" + tag,
                  adhesion.fraction,
                  1e-3);
      check_between("contact conditions met" + tag,
                    contact.is_satisfied(),
                    1,
                    1);
      for (unsigned int k = 0; k < 3; ++k)
        check_below("force balance, component " + std::to_string(k) +
                      " (relative to the weight)" + tag,
                    std::abs(balance[k]) / weight.norm(),
                    1e-8);
    }
  std::filesystem::remove(mesh_file);
  std::filesystem::remove(bowl_file);
  check_below("relative change of the sag with fixed planes",
              std::abs(sag[1] - sag[0]) / sag[0],
              1e-3);
  return exit_code();
}
