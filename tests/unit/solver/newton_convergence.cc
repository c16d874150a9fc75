// Newton on a large-rotation case: a soft cantilever (100 x 10 x 10 mm,
// E = 100 kPa) bending under its own weight until its tip hangs 66 mm down.
// The consistent tangent must converge quadratically (order >= 1.8 over the
// last steps); the warped (SOFA) tangent reaches the same equilibrium but
// needs more iterations. The projected tangent (negative eigenvalues of
// compressed points removed) and the adaptive one (consistent, projected
// after a shortened step) reach the same equilibrium; adaptive keeps the
// quadratic order at the end. A cap on the Newton iterations equal to the
// count the consistent tangent needs still converges (the state the last
// allowed step reaches is checked), one less does not. A failed load
// increment is retried half as far, also when it was cut at the full load.
// All counts are printed for the record.
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  struct Result
  {
    SolveStatistics stats;
    double          tip_mm;
  };

  Result
  solve(const std::string &tangent,
        const std::string &solver = " set Maximum Newton iterations = 200\n")
  {
    Scene s(
      "subsection Mesh\n set File = meshes/cantilever_tet.msh\nend\n"
      "subsection Discretization\n set Polynomial degree = 2\n set Tangent = " +
      tangent +
      "\nend\nsubsection Materials\n set Young's modulus = 100000\n"
      " set Poisson's ratio = 0.3\n set Density = 1000\nend\n"
      "subsection Boundary conditions\n set Fixed labels = 2\nend\n"
      "subsection Solver\n" +
      solver + "end\n");
    ForwardProblem &f = *s.forward;
    Result          r;
    r.stats = f.solve(f.loads().scene_load(), f.discretization().zero_vector());
    r.tip_mm = 0;
    for (const Node &node : f.discretization().owned_nodes())
      r.tip_mm = std::max(r.tip_mm, -f.displacement()[node.dofs[2]] * 1e3);
    return r;
  }

  /// Estimated order p from the last three residuals: r3/r2 = (r2/r1)^p.
  double
  order(const std::vector<double> &r)
  {
    const unsigned int n = r.size();
    return std::log(r[n - 1] / r[n - 2]) / std::log(r[n - 2] / r[n - 3]);
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Result                     consistent = solve("consistent");
  const Result                     warped     = solve("warped");
  const Result                     projected  = solve("projected");
  const Result                     adaptive   = solve("adaptive");
  std::cout << "Newton iterations: consistent "
            << consistent.stats.newton_iterations << ", warped "
            << warped.stats.newton_iterations << ", projected "
            << projected.stats.newton_iterations << ", adaptive "
            << adaptive.stats.newton_iterations << "; tip deflection "
            << consistent.tip_mm << " mm" << std::endl;
  std::cout << "consistent |R|/|f| history:";
  for (const double r : consistent.stats.residual_history)
    std::cout << ' ' << r;
  std::cout << std::endl;

  check_between("consistent converged", consistent.stats.converged, 1, 1);
  check_between("warped converged", warped.stats.converged, 1, 1);
  check_between("tip deflection (mm): a large-rotation case",
                consistent.tip_mm,
                40,
                100);
  check_between("consistent: convergence order of the last steps",
                order(consistent.stats.residual_history),
                1.8,
                100);
  check_between("warped needs more iterations (ratio warped/consistent)",
                double(warped.stats.newton_iterations) /
                  consistent.stats.newton_iterations,
                1.5,
                100);
  check_below("both tangents reach the same equilibrium (tip difference, mm)",
              std::abs(consistent.tip_mm - warped.tip_mm),
              1e-6);
  check_between("projected converged", projected.stats.converged, 1, 1);
  check_between("adaptive converged", adaptive.stats.converged, 1, 1);
  check_below("projected: same equilibrium (tip difference, mm)",
              std::abs(consistent.tip_mm - projected.tip_mm),
              1e-6);
  check_below("adaptive: same equilibrium (tip difference, mm)",
              std::abs(consistent.tip_mm - adaptive.tip_mm),
              1e-6);
  check_between("adaptive: convergence order of the last steps",
                order(adaptive.stats.residual_history),
                1.8,
                100);

  const auto capped = [&](const unsigned int cap) {
    return solve("consistent",
                 " set Maximum Newton iterations = " + std::to_string(cap) +
                   "\n set Maximum load step halvings = 0\n");
  };
  const unsigned int n        = consistent.stats.newton_iterations;
  const Result       at_cap   = capped(n);
  const Result       over_cap = capped(n - 1);
  std::cout << "cap " << n << ": converged " << at_cap.stats.converged
            << "; cap " << n - 1 << ": " << over_cap.stats.failure << std::endl;
  check_between("cap = the count needed: converged",
                at_cap.stats.converged,
                1,
                1);
  check_below("cap = the count needed: same equilibrium (tip difference, mm)",
              std::abs(consistent.tip_mm - at_cap.tip_mm),
              1e-9);
  check_between("cap = one less: not converged",
                over_cap.stats.converged,
                0,
                0);

  // Load increments: from a quarter, accepted twice (to 0.25, then 0.75),
  // the next is cut at the full load (0.25 of the way); when it fails, the
  // retry must go half as far (to 0.875), not to 1 again, and accepting
  // that leaves 0.125 to go.
  LoadSteps steps{0, 0.25};
  steps.accept(steps.next());
  steps.accept(steps.next());
  const double cut = steps.next();
  steps.reject(cut);
  const double retry = steps.next();
  steps.accept(retry);
  std::cout << "load steps: 0.25, 0.75, " << cut << " failed, then " << retry
            << ", then " << steps.next() << std::endl;
  check_between("load step cut at the full load", cut, 1, 1);
  check_between("retry after a failed cut step", retry, 0.875, 0.875);
  check_between("step after the retry", steps.next(), 1, 1);
  return exit_code();
}
