// The two linear solvers reach the same equilibrium: the soft cantilever
// (large rotations) solved with MUMPS and with CG + ML AMG (rigid-body-mode
// null space), for P1 tetrahedra and Q1 hexahedra; CG + AMG also with
// Inexact Newton, with the AMG aggregates of the first Newton step reused
// in the later ones, and with a lagged AMG (the tangent changes a lot
// between the steps of this large rotation); all with the default AMG
// aggregation threshold 0 and once with 0.02, with the default plain
// aggregation and once smoothed. Solved half way, the linear solver's
// factorisation or AMG released, then solved to the whole load, the
// equilibrium is the same (the next solve builds them again). Prints Newton
// and linear iteration counts.
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>
#include <restshape/loads/load_state.h>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  VectorType
  solve(const std::string &cell_type,
        const std::string &solver,
        const std::string &options,
        SolveStatistics   &stats,
        const bool         release_half_way = false)
  {
    Scene s(
      "subsection Mesh\n set File = meshes/cantilever_tet.msh\n set Cell type = " +
      cell_type +
      "\nend\nsubsection Materials\n set Young's modulus = 100000\n"
      " set Poisson's ratio = 0.3\n set Density = 1000\nend\n"
      "subsection Boundary conditions\n set Fixed labels = 2\nend\n"
      "subsection Solver\n set Linear solver = " +
      solver + "\n set Linear solver tolerance = 1e-8\n" + options + "end\n");
    ForwardProblem &f = *s.forward;
    if (release_half_way)
      {
        // Half the load, release the solver, then the whole load: the
        // second solve builds the factorisation or AMG again.
        const SolveStatistics half =
          f.solve(between(LoadState(), f.loads().scene_load(), 0.5),
                  f.discretization().zero_vector());
        check_between(cell_type + ", " + solver + ": half load converged",
                      half.converged,
                      1,
                      1);
        f.release_linear_solver();
      }
    stats = f.solve(f.loads().scene_load(), f.discretization().zero_vector());
    VectorType d = f.discretization().zero_vector();
    d            = f.displacement();
    return d;
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string cell_type : {"tetrahedra", "hexahedra"})
    {
      SolveStatistics  direct_stats;
      const VectorType direct =
        solve(cell_type, "direct", "", direct_stats, true);
      check_between(cell_type + ": direct converged",
                    direct_stats.converged,
                    1,
                    1);
      const std::string last = " set Inexact Newton = true\n set AMG update = "
                               "lagged\n set AMG prolongator = smoothed\n";
      for (const std::string options :
           {" set Inexact Newton = false\n set AMG update = rebuild\n",
            " set Inexact Newton = true\n set AMG update = rebuild\n",
            " set Inexact Newton = false\n set AMG update = reuse aggregates\n",
            " set Inexact Newton = false\n set AMG update = lagged\n",
            " set Inexact Newton = true\n set AMG update = lagged\n",
            " set Inexact Newton = true\n set AMG update = lagged\n"
            " set AMG aggregation threshold = 0.02\n",
            " set Inexact Newton = true\n set AMG update = lagged\n"
            " set AMG prolongator = smoothed\n"})
        {
          const std::string name =
            cell_type + ", cg-amg" +
            (options.find("= true") != std::string::npos ? " inexact" : "") +
            (options.find("reuse") != std::string::npos ? " reuse" : "") +
            (options.find("lagged") != std::string::npos ? " lagged" : "") +
            (options.find("threshold") != std::string::npos ?
               " aggregation threshold 0.02" :
               "") +
            (options.find("smoothed") != std::string::npos ? " smoothed" : "");
          SolveStatistics amg_stats;
          VectorType      amg =
            solve(cell_type, "cg-amg", options, amg_stats, options == last);
          std::cout << name << ": Newton iterations "
                    << amg_stats.newton_iterations << " (direct "
                    << direct_stats.newton_iterations << "), "
                    << amg_stats.linear_iterations
                    << " CG/GMRES iterations in all" << std::endl;
          check_between(name + ": converged", amg_stats.converged, 1, 1);
          amg -= direct;
          check_below(name + ": |d_amg - d_direct| / |d_direct|",
                      amg.l2_norm() / direct.l2_norm(),
                      1e-7);
        }
    }
  return exit_code();
}
