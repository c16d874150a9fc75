// The error indicators of source/error_estimator.cc on fields whose
// traction is continuous, so that the discretisation has nothing to
// estimate, on the Q1 column (label 1 above z = 10 mm, label 2 below):
//
// 1. Two materials (E 1 and 10 kPa, nu = 0) under a uniform axial stress:
//    u_z is piecewise linear with a kink at the interface, represented
//    exactly by Q1. The traction jump must be zero; Kelly sees the kink.
// 2. A rigid support (label 2 fixed) under uniformly strained tissue: the
//    same, the faces of the fixed cells being no error.
// 3. A rigid rotation by 40 degrees: both zero.
// 4. A trilinear field in one material on a mesh with hanging nodes: both
//    zero (the gradient is continuous but varies along the faces).
// Runs on 1 and on 2 MPI ranks (tests/CMakeLists.txt).
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>
#include <restshape/postprocess/error_estimator.h>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  const std::string mesh =
    "subsection Mesh\n set File = meshes/column_hex.msh\n set Length unit = "
    "mm\n set Cell type = hexahedra\nend\n"
    "subsection Discretization\n set Polynomial degree = 1\nend\n";
  const std::string two_materials =
    "subsection Materials\n set Young's modulus = 1:1000, 2:10000\n"
    " set Poisson's ratio = 0\n set Density = 1000\nend\n";

  /// u = f(X) at every node, then both estimates (relative totals).
  /// With @p hanging, 30 % of the cells (every third) refined first.
  template <typename Field>
  std::pair<double, double>
  estimates(const std::string &fixed,
            const Field       &field,
            const bool         hanging   = false,
            const std::string &materials = two_materials)
  {
    Scene s(mesh + materials +
            "subsection Boundary conditions\n set Fixed labels = " + fixed +
            "\nend\n");
    if (hanging)
      {
        Vector<float> marks(s.mesh->triangulation().n_active_cells());
        for (unsigned int i = 0; i < marks.size(); i += 3)
          marks[i] = 1;
        s.mesh->refine_adaptive(marks, 0.3, 0);
        s.forward->setup();
      }
    ForwardProblem  &f = *s.forward;
    const VectorType u = nodal_field(f, field);
    return {
      estimate_error(f, u, RefinementParameters::Estimator::kelly).relative,
      estimate_error(f, u, RefinementParameters::Estimator::traction_jump)
        .relative};
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     z0 = 0.010; // the interface, m

  // 1. Stress 10 Pa along z: strain 1e-2 in label 1, 1e-3 in label 2; the
  // bottom face (z = 0) held in z.
  const auto axial = [&](const Point<3> &X) {
    const double z = X[2];
    return Tensor<1, 3>(
      {0, 0, z < z0 ? 1e-3 * z : 1e-3 * z0 + 1e-2 * (z - z0)});
  };
  const auto [kelly1, traction1] = estimates("2:z", axial);
  std::cout << "two materials: Kelly " << kelly1 << ", traction jump "
            << traction1 << std::endl;
  check_below("two materials: traction jump", traction1, 1e-12);
  check_between("two materials: Kelly sees the kink", kelly1, 0.01, 10);
  // The same with hanging nodes (faces seen from their finer and their
  // coarser side).
  const auto [kelly1h, traction1h] = estimates("2:z", axial, true);
  std::cout << "two materials, hanging nodes: Kelly " << kelly1h
            << ", traction jump " << traction1h << std::endl;
  check_below("two materials, hanging nodes: traction jump", traction1h, 1e-12);
  check_between("two materials, hanging nodes: Kelly", kelly1h, 0.01, 10);

  // 2. Label 2 rigid, label 1 stretched by 1 % along z from the support.
  const auto [kelly2, traction2] = estimates("2", [&](const Point<3> &X) {
    return Tensor<1, 3>({0, 0, X[2] < z0 ? 0 : 1e-2 * (X[2] - z0)});
  });
  std::cout << "rigid support: Kelly " << kelly2 << ", traction jump "
            << traction2 << std::endl;
  check_below("rigid support: traction jump", traction2, 1e-12);
  check_between("rigid support: Kelly sees the support", kelly2, 0.01, 10);

  // 3. x = R X, R 40 degrees about (1, 1, 1), nothing fixed: no strain
  // anywhere (the law is rotation invariant; grad u is constant).
  const Tensor2 R =
    rotation(40. * numbers::PI / 180 / std::sqrt(3.) * Tensor<1, 3>({1, 1, 1}));
  const auto [kelly3, traction3] = estimates("", [&](const Point<3> &X) {
    return Tensor<1, 3>(R * Tensor<1, 3>(X) - Tensor<1, 3>(X));
  });
  std::cout << "rigid rotation: Kelly " << kelly3 << ", traction jump "
            << traction3 << std::endl;
  check_below("rigid rotation: Kelly", kelly3, 1e-12);
  check_below("rigid rotation: traction jump", traction3, 1e-12);

  // 4. A trilinear field in one material (nu 0.3), hanging nodes: grad u
  // is one polynomial, continuous across every face, but varies along the
  // faces, so matching the wrong points of a subface would show.
  const auto [kelly4, traction4] = estimates(
    "",
    [&](const Point<3> &X) {
      const Point<3> Y = X * 100; // m -> 1/10 mm: values of order 1e-3 m
      return Tensor<1, 3>({1e-4 * Y[0] * Y[1] * Y[2], 2e-4 * Y[1] * Y[2], 0});
    },
    true,
    "subsection Materials\n set Young's modulus = 1000\n"
    " set Poisson's ratio = 0.3\n set Density = 1000\nend\n");
  std::cout << "trilinear field, hanging nodes: Kelly " << kelly4
            << ", traction jump " << traction4 << std::endl;
  check_below("trilinear field, hanging nodes: Kelly", kelly4, 1e-10);
  check_below("trilinear field, hanging nodes: traction jump",
              traction4,
              1e-10);
  return exit_code();
}
