// Co-rotational invariance and tangent consistency.
//
// 1. Material point: a rotation R0 gives P = 0; P(R0 F) = R0 P(F); the
//    consistent tangent matches central differences of P; the warped one
//    does not (it omits dR/dF) but agrees at F = R0.
// 2. Assembled problem (P1 and P2 tetrahedra, Q1 hexahedra): a rigid
//    rotation of the whole body by 40 degrees gives zero internal force; the
//    assembled tangent matches central differences of the assembled
//    residual at a deformed state.
// 3. Projected tangent: under compression the consistent tangent has
//    negative eigenvalues (rotational modes); the projected one has exactly
//    the consistent spectrum with those set to zero, and equals the
//    consistent tangent where that is positive (stretch).
#include <deal.II/base/mpi.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <restshape/base/mpi_start.h>

#include <algorithm>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  void
  material_point_checks()
  {
    const CorotationalLaw law(1500., 0.45);
    const Tensor2         R0 = rotation(Tensor<1, 3>({0.3, -0.5, 0.8}));
    Tensor2               P;
    law.evaluate(R0, P, nullptr, TangentType::consistent);
    check_below("material: |P(R0)| / mu (rigid rotation, Pa/Pa)",
                P.norm() / law.mu,
                1e-12);

    Tensor2 F;
    F[0][0] = 1.1, F[0][1] = 0.3, F[0][2] = -0.1;
    F[1][0] = -0.2, F[1][1] = 0.9, F[1][2] = 0.15;
    F[2][0] = 0.05, F[2][1] = 0.1, F[2][2] = 1.2;
    Tensor2 P_F, P_RF;
    law.evaluate(F, P_F, nullptr, TangentType::consistent);
    law.evaluate(R0 * F, P_RF, nullptr, TangentType::consistent);
    check_below("material: |P(R0 F) - R0 P(F)| / |P(F)|",
                (P_RF - R0 * P_F).norm() / P_F.norm(),
                1e-12);

    check_below(
      "material: consistent tangent vs central differences (relative)",
      tangent_error(law, F, TangentType::consistent),
      1e-6);
    check_between(
      "material: warped tangent vs central differences (relative, must differ)",
      tangent_error(law, F, TangentType::warped),
      1e-3,
      10);
    check_below("material: warped tangent at F = R0 (relative)",
                tangent_error(law, R0, TangentType::warped),
                1e-6);

    // P = dW/dF.
    Tensor2 dW;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int L = 0; L < 3; ++L)
        {
          Tensor2 Fp = F, Fm = F;
          Fp[k][L] += 1e-6;
          Fm[k][L] -= 1e-6;
          dW[k][L] = (law.energy_density(Fp) - law.energy_density(Fm)) / 2e-6;
        }
    check_below("material: |P - dW/dF| / |P|",
                (P_F - dW).norm() / P_F.norm(),
                1e-6);
  }

  // Sorted eigenvalues of dP/dF as a symmetric 9x9 matrix (it is the
  // Hessian of W), and its asymmetry.
  std::vector<double>
  spectrum(const CorotationalLaw &law,
           const Tensor2         &F,
           const TangentType      type,
           double                &asymmetry)
  {
    Tensor2 P;
    Tensor4 A;
    law.evaluate(F, P, &A, type);
    LAPACKFullMatrix<double> M(9, 9);
    asymmetry = 0;
    for (unsigned int a = 0; a < 9; ++a)
      for (unsigned int b = 0; b < 9; ++b)
        {
          M(a, b) = A[a / 3][a % 3][b / 3][b % 3];
          asymmetry =
            std::max(asymmetry,
                     std::abs(M(a, b) - A[b / 3][b % 3][a / 3][a % 3]));
        }
    M.compute_eigenvalues();
    std::vector<double> values(9);
    for (unsigned int a = 0; a < 9; ++a)
      values[a] = M.eigenvalue(a).real();
    std::sort(values.begin(), values.end());
    return values;
  }

  void
  projected_tangent_checks()
  {
    const CorotationalLaw law(1500., 0.45);
    const Tensor2         R0 = rotation(Tensor<1, 3>({0.3, -0.5, 0.8}));
    Tensor2               U;
    U[0][0] = 0.85, U[1][1] = 0.92, U[2][2] = 0.97;
    U[0][1] = U[1][0] = 0.03;
    U[1][2] = U[2][1]        = -0.02;
    const Tensor2 compressed = R0 * U; // 24 % volume loss
    double        asymmetry;
    const auto    consistent =
      spectrum(law, compressed, TangentType::consistent, asymmetry);
    check_below("projected: asymmetry of the consistent tangent / mu",
                asymmetry / law.mu,
                1e-10);
    check_below(
      "projected: smallest consistent eigenvalue / mu (compressed, must be < 0)",
      consistent[0] / law.mu,
      -0.1);
    const auto projected =
      spectrum(law, compressed, TangentType::projected, asymmetry);
    check_below("projected: asymmetry of the projected tangent / mu",
                asymmetry / law.mu,
                1e-10);
    std::vector<double> clamped = consistent;
    for (double &v : clamped)
      v = std::max(v, 0.);
    std::sort(clamped.begin(), clamped.end());
    double difference = 0;
    for (unsigned int a = 0; a < 9; ++a)
      difference = std::max(difference, std::abs(projected[a] - clamped[a]));
    check_below(
      "projected: |spectrum - max(consistent spectrum, 0)| / mu (compressed)",
      difference / law.mu,
      1e-9);

    Tensor2 V = U;
    V[0][0] = 1.1, V[1][1] = 1.05, V[2][2] = 1.02;
    Tensor2 P;
    Tensor4 A_c, A_p;
    law.evaluate(R0 * V, P, &A_c, TangentType::consistent);
    law.evaluate(R0 * V, P, &A_p, TangentType::projected);
    check_below(
      "projected: |projected - consistent| / |consistent| (stretched)",
      (A_p - A_c).norm() / A_c.norm(),
      1e-14);
  }

  std::string
  scene(const std::string &cell_type, const unsigned int degree)
  {
    return "subsection Mesh\n set File = meshes/cantilever_tet.msh\n set Cell type = " +
           cell_type +
           "\nend\nsubsection Discretization\n set Polynomial degree = " +
           std::to_string(degree) +
           "\nend\nsubsection Materials\n set Young's modulus = 1:1500, 2:15000\n"
           " set Poisson's ratio = 0.45\n set Density = 1000\nend\n"
           "subsection Boundary conditions\n set Fixed labels = 2\nend\n";
  }

  void
  assembled_checks(const std::string &cell_type, const unsigned int degree)
  {
    const std::string name = cell_type + " degree " + std::to_string(degree);
    Scene             s(scene(cell_type, degree));
    ForwardProblem   &f = *s.forward;

    // Rigid rotation of every node about an axis through (0.05, 0, 0) m.
    const Tensor2  R0 = rotation(Tensor<1, 3>({0.2, 0.5, 0.4})); // ~0.67 rad
    const Point<3> center(0.05, 0, 0);
    VectorType     d = f.discretization().zero_vector(),
               w     = f.discretization().zero_vector();
    for (const Node &node : f.discretization().owned_nodes())
      {
        const Tensor<1, 3> u =
          R0 * (node.position - center) - (node.position - center);
        for (unsigned int c = 0; c < 3; ++c)
          d[node.dofs[c]] = u[c];
      }
    LoadState no_load;
    f.set_state(d, w, no_load);
    f.evaluate();
    // Scale: the internal force of a 1 % stretch.
    VectorType stretch = f.discretization().zero_vector();
    for (const Node &node : f.discretization().owned_nodes())
      stretch[node.dofs[0]] = 0.01 * node.position[0];
    f.set_state(stretch, w, no_load);
    f.evaluate();
    const double scale = f.raw_residual().l2_norm();
    f.set_state(d, w, no_load);
    f.evaluate();
    check_below(name + ": |f_int(rigid rotation)| / |f_int(1% stretch)|",
                f.raw_residual().l2_norm() / scale,
                1e-10);

    // Tangent against central differences of the residual, at a bent and
    // rotated state, along a random direction v (zero at fixed DoFs).
    VectorType   state = d, v = f.discretization().zero_vector();
    unsigned int seed   = 1;
    const auto   random = [&seed]() {
      seed = 1103515245u * seed + 12345u;
      return double(seed % 10000) / 10000. - 0.5;
    };
    for (const Node &node : f.discretization().owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        {
          state[node.dofs[c]] += 0.002 * random() * node.position[0] / 0.1;
          if (!f.discretization().is_fixed(node.dofs[c]))
            v[node.dofs[c]] = 1e-3 * random();
        }
    f.set_state(state, w, no_load);
    f.evaluate(true);
    VectorType Kv = f.discretization().zero_vector();
    f.tangent_matrix().vmult(Kv, v);
    const double h  = 1e-4;
    VectorType   sp = state, sm = state;
    sp.add(h, v);
    sm.add(-h, v);
    f.set_state(sp, w, no_load);
    f.evaluate();
    VectorType diff = f.raw_residual();
    f.set_state(sm, w, no_load);
    f.evaluate();
    diff -= f.raw_residual();
    diff /= 2 * h; // = -K v at free DoFs
    double error = 0, norm = 0;
    for (const Node &node : f.discretization().owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        if (!f.discretization().is_fixed(node.dofs[c]))
          {
            error += std::pow(diff[node.dofs[c]] + Kv[node.dofs[c]], 2);
            norm += std::pow(Kv[node.dofs[c]], 2);
          }
    check_below(
      name + ": assembled consistent tangent vs central differences (relative)",
      std::sqrt(error / norm),
      1e-6);
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  material_point_checks();
  projected_tangent_checks();
  assembled_checks("tetrahedra", 1);
  assembled_checks("tetrahedra", 2);
  assembled_checks("hexahedra", 1);
  return exit_code();
}
