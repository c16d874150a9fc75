// The mixed formulation's tangent (Discretization/Formulation = mixed: the
// isochoric law at each point and the volumetric energy of each cell's
// mean dilatation; on linear tetrahedra that of the vertices' volumes,
// where the cantilever's two labels share vertices) is the derivative of
// its residual: on the cantilever (P1 and P2 tetrahedra, Q1 and Q2
// hexahedra) at nu = 0.4999, for every law, at a deformed state (a bend
// and a squeeze of the free part), K v against central differences of the
// residual along a smooth v; and the residual is the derivative of the
// energy (central differences along v). Linear tetrahedra also with
// Discretization/Nodal pressure at the boundary = interior (boundary
// vertices give their shares of the cells' volumes to interior ones);
// quadratic hexahedra with both pressures per cell, linear (Q2-P1disc, the
// default) and constant (Q2-P0).
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>

#include <cmath>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  std::string
  prm_text(const std::string &cell_type,
           const unsigned int degree,
           const std::string &law,
           const std::string &option)
  {
    return "subsection Mesh\n set File = meshes/cantilever_tet.msh\n"
           " set Length unit = mm\n set Cell type = " +
           cell_type +
           "\nend\n"
           "subsection Discretization\n set Polynomial degree = " +
           std::to_string(degree) + "\n set Formulation = mixed\n set " +
           option +
           "\nend\n"
           "subsection Materials\n set Young's modulus = 100000\n"
           " set Poisson's ratio = 0.4999\n set Density = 1000\n"
           " set Material law = " +
           law +
           "\nend\n"
           "subsection Boundary conditions\n set Fixed labels = 2\nend\n"
           "subsection Loads\n set Gravity = 0, 0, -9.81\nend\n";
  }

  /// A smooth field on the mesh (m), zero on the clamp (x < 10 mm).
  VectorType
  field(const Scene &s, const double bend, const double squeeze)
  {
    const auto               &tria = s.mesh->triangulation();
    std::vector<Tensor<1, 3>> values(tria.n_vertices());
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      {
        const Point<3> x = tria.get_vertices()[v];
        const double   a = std::max(0., x[0] - 0.01) / 0.09;
        values[v][2]     = bend * a * a * 0.01;
        values[v][1]     = squeeze * a * (x[1] - 0.005);
        values[v][0]     = 0.3 * squeeze * a * std::sin(200 * x[2]) * 0.01;
      }
    return s.forward->discretization().interpolate_vertex_field(values);
  }

  const std::string own = "Nodal pressure at the boundary = own";

  void
  check(const std::string &cell_type,
        const unsigned int degree,
        const std::string &law,
        const std::string &option = own)
  {
    Scene             s(prm_text(cell_type, degree, law, option));
    ForwardProblem   &f    = *s.forward;
    const LoadState   load = f.loads().scene_load();
    const VectorType  w    = f.discretization().zero_vector();
    const VectorType  d    = field(s, 0.5, 0.05);
    const VectorType  v    = field(s, 0.3, -0.2);
    const std::string name = cell_type + " P" + std::to_string(degree) + " " +
                             law + (option == own ? "" : " (" + option + ")") +
                             ": ";
    constexpr double h           = 1e-7;
    const auto       residual_at = [&](const double t, double *energy) {
      VectorType x = d;
      x.add(t, v);
      f.set_state(x, w, load);
      f.evaluate(false);
      if (energy != nullptr)
        *energy = f.potential_energy();
      return f.discretization().owned_copy(f.raw_residual());
    };
    double     e_plus = 0, e_minus = 0;
    VectorType r_plus  = residual_at(h, &e_plus);
    VectorType r_minus = residual_at(-h, &e_minus);
    f.set_state(d, w, load);
    check_between(name + "state valid", f.evaluate(true), 1, 1);
    const VectorType r  = f.discretization().owned_copy(f.raw_residual());
    VectorType       Kv = f.discretization().zero_vector();
    f.tangent_matrix().vmult(Kv, v);
    // -dR/dd v against K v on the rows no constraint touches.
    double error = 0, size = 0;
    for (const auto i : Kv.locally_owned_elements())
      {
        if (f.newton_constraints().is_constrained(i))
          continue;
        const double fd = -(r_plus[i] - r_minus[i]) / (2 * h);
        error           = std::max(error, std::abs(fd - Kv[i]));
        size            = std::max(size, std::abs(Kv[i]));
      }
    check_below(name + "tangent against differences of the residual",
                error / size,
                1e-5);
    // dE/dd v = -R v (R = f_ext - f_int).
    const double slope = (e_plus - e_minus) / (2 * h);
    double       Rv    = 0;
    for (const auto i : v.locally_owned_elements())
      if (!f.newton_constraints().is_constrained(i))
        Rv += r[i] * v[i];
    check_below(name + "residual against differences of the energy",
                std::abs(slope + Rv) / std::abs(Rv),
                1e-5);
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string law : {"neo-Hookean", "corotational", "Ogden"})
    {
      check("tetrahedra", 1, law);
      check("tetrahedra", 1, law, "Nodal pressure at the boundary = interior");
      check("tetrahedra", 2, law);
      check("hexahedra", 1, law);
    }
  check("hexahedra", 2, "neo-Hookean", "Cell pressure = linear");
  check("hexahedra", 2, "Ogden", "Cell pressure = linear");
  check("hexahedra", 2, "neo-Hookean", "Cell pressure = constant");
  return exit_code();
}
