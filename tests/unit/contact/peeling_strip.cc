// A strip peeling off a floor: the strict contact conditions decide where
// it lifts off. The strip (100 x 10 x 1 mm, P2, E = 10 MPa) lies on a rigid
// floor in a fluid of 1000 kg/m^3; its part of 2000 kg/m^3 weighs
// q = 1000 g A per metre, its last 10 mm (density 0) lift with the same q.
// Beam theory on a rigid foundation: the bending moment vanishes where the
// strip leaves the floor, (100 - x_l)^2 = 2 (90 - x_l)^2 (mm), so it lifts
// off over a = 100 - x_l = 34.14 mm (the 3D strip: 32.5 mm, the contact
// reaction near the edge spreading over about the thickness). Without the
// strict check of the converged state the solver stopped with 8 nodes
// pulling by up to 5.7 kPa and the strip held down from 16 mm (11 mm with
// one free update).
// Checked with the default active set and with Free active-set updates = 1:
// the solve converges, the contact conditions hold against the floor (no
// node through it, none off it while active, none pulling), the contact
// force balances the buoyed weight, and a is within 5 % of beam theory.
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>
#include <restshape/contact/contact_report.h>

#include <algorithm>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  std::string
  prm_text(const unsigned int free_updates)
  {
    return "subsection Mesh\n set File = meshes/strip_tet.msh\n"
           " set Length unit = mm\nend\n"
           "subsection Discretization\n set Polynomial degree = 2\nend\n"
           "subsection Materials\n set Young's modulus = 1e7\n"
           " set Poisson's ratio = 0.3\n set Density = 1:2000, 2:0, 3:2000\n"
           "end\n"
           "subsection Boundary conditions\n set Fixed labels = 3:xy\nend\n"
           "subsection Loads\n set Gravity = 0, 0, -9.81\n"
           " set Fluid density = 1000\nend\n"
           "subsection Solver\n set Maximum Newton iterations = 400\nend\n"
           "subsection Contact\n set Obstacle file = meshes/floor_strip.off\n"
           " set Side = outside\n set Free active-set updates = " +
           std::to_string(free_updates) + "\nend\n";
  }

  void
  check(const unsigned int free_updates)
  {
    const std::string name =
      "free active-set updates " + std::to_string(free_updates);
    Scene           s(prm_text(free_updates));
    ContactProblem &contact = s.add_contact();
    ForwardProblem &f       = *s.forward;
    const auto      stats =
      f.solve(f.loads().scene_load(), f.discretization().zero_vector());
    if (!stats.converged)
      std::cout << name << ": " << stats.failure << std::endl;
    check_between(name + ": converged", stats.converged, 1, 1);
    const ContactConditions &conditions = f.contact_conditions();
    std::cout << name << ": " << stats.newton_iterations
              << " Newton iterations; " << conditions.text() << std::endl;
    check_between(name + ": the contact conditions hold",
                  conditions.satisfied(),
                  1,
                  1);

    // The buoyed weight (N), carried by the floor: (2000 - 1000) g V_heavy
    // - 1000 g V_end with V = 1e-5 m^2 times 0.09 and 0.01 m.
    const double weight = 9.81 * (1000 * 1e-5 * 0.09 - 1000 * 1e-5 * 0.01);
    const double force =
      ContactReport(contact).total_force(f.raw_residual())[2];
    check_below(name + ": contact force against the buoyed weight (rel.)",
                std::abs(force - weight) / weight,
                1e-8);

    // Where it lifts off: the last active node from the clamp's side.
    const VectorType fields =
      ContactReport(contact).nodal_fields(f.raw_residual(), 1e3);
    double front = 0;
    for (const Node &node : f.discretization().owned_nodes())
      if (fields[node.dofs[0]] > 0.5)
        front = std::max(front, node.position[0]);
    front               = Utilities::MPI::max(front, MPI_COMM_WORLD);
    const double lifted = 100 - 1e3 * front;
    const double x_l    = (90 * std::sqrt(2.) - 100) / (std::sqrt(2.) - 1);
    const double theory = 100 - x_l;
    std::cout << name << ": lifts off over " << lifted << " mm (beam theory "
              << theory << " mm)" << std::endl;
    check_below(name + ": lift-off length against beam theory (rel.)",
                std::abs(lifted - theory) / theory,
                0.05);
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check(10);
  check(1);
  return exit_code();
}
