// The inverse (rest-shape) iteration.
//
// 1. Gravity column (nu = 0, E = 10 kPa, P2): Anderson acceleration and the
//    paper's plain update reach the same rest shape; Anderson needs fewer
//    iterations (both counts printed).
// 2. Contact is what makes the plain update converge on soft bodies (Morin
//    et al. 2015): a plate 10 mm thin, E = 10 kPa, standing under its own
//    weight at 96 % of its buckling load in x. A rest shape tilted in x is
//    stress-free but its equilibrium tilts ~25 times more, so the plain
//    update diverges. Frictionless walls touching the plate's x faces (a
//    closed slot, Side = inside) hold that mode and the plain update
//    converges; Anderson converges even without the walls.
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>
#include <restshape/contact/contact.h>
#include <restshape/inverse/inverse_problem.h>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  struct Run
  {
    InverseResult result;
    VectorType    rest;
  };

  Run
  run(const std::string &mesh,
      const std::string &acceleration,
      const std::string &obstacle)
  {
    Scene s(
      "subsection Mesh\n set File = " + mesh +
      "\nend\nsubsection Discretization\n set Polynomial degree = 2\nend\n"
      "subsection Materials\n set Young's modulus = 10000\n set Poisson's ratio = 0\n"
      " set Density = 1000\nend\n"
      "subsection Boundary conditions\n set Fixed labels = 2\nend\n"
      "subsection Contact\n set Obstacle file = " +
      obstacle +
      "\nend\n"
      "subsection Inverse problem\n set Enabled = true\n set Tolerance = 1e-8\n"
      " set Method = fixed point\n"
      " set Acceleration = " +
      acceleration + "\nend\n");
    ContactProblem *contact = obstacle.empty() ? nullptr : &s.add_contact();
    Timer           wall;
    InverseProblem  inverse(s.parameters.inverse,
                           *s.forward,
                           contact,
                           nullptr,
                           s.timer,
                           s.pcout,
                           wall);
    Run             r;
    r.result = inverse.run(s.forward->discretization().zero_vector(), 0);
    r.rest   = s.forward->discretization().zero_vector();
    r.rest   = s.forward->rest_displacement();
    std::cout << mesh << ", " << acceleration
              << (obstacle.empty() ? "" : ", " + obstacle) << ": "
              << (r.result.converged ? "converged" :
                                       "stopped (" + r.result.reason + ")")
              << " after " << r.result.iterations << " iterations, "
              << r.result.forward_solves << " forward solves, mean error "
              << r.result.mean_error * 1e3 << " mm" << std::endl;
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const Run plain    = run("meshes/column_tet.msh", "none", "");
  const Run anderson = run("meshes/column_tet.msh", "anderson", "");
  check_between("column: plain update converged", plain.result.converged, 1, 1);
  check_between("column: Anderson converged", anderson.result.converged, 1, 1);
  VectorType difference = plain.rest;
  difference -= anderson.rest;
  check_below("column: same rest shape, |w_plain - w_anderson| / |w|",
              difference.l2_norm() / plain.rest.l2_norm(),
              1e-6);
  check_below("column: Anderson iterations / plain iterations",
              double(anderson.result.iterations) / plain.result.iterations,
              1);

  const Run free_plain = run("meshes/plate_tet.msh", "none", "");
  const Run slot_plain =
    run("meshes/plate_tet.msh", "none", "meshes/plate_slot.off");
  const Run free_anderson = run("meshes/plate_tet.msh", "anderson", "");
  check_between("plate without walls: the plain update diverges",
                !free_plain.result.converged &&
                  free_plain.result.reason.find("diverged") !=
                    std::string::npos,
                1,
                1);
  check_between("plate in the slot: the plain update converges",
                slot_plain.result.converged,
                1,
                1);
  check_between("plate without walls: Anderson converges",
                free_anderson.result.converged,
                1,
                1);
  return exit_code();
}
