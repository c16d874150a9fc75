// ElasticCell against the plain loop over the vector element's shape
// functions that it replaced, on one cell of each element (P1, P2
// tetrahedra, Q1, Q2 hexahedra) at a few quadrature points with random
// states: a tangent with major symmetry (as every hyperelastic law's),
// random stresses, body forces and rest-configuration maps. The residual,
// the external force, the magnitudes and the tangent must be the same to
// the last bit (the same products added in the same order), and the
// tangent symmetric; a residual-only cell must give the same vectors.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <restshape/fem/elastic_cell.h>

#include <iostream>
#include <memory>
#include <random>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  std::mt19937                           random_engine(7);
  std::uniform_real_distribution<double> uniform(-1., 1.);

  Tensor2
  random_tensor(const double scale, const bool near_identity)
  {
    Tensor2 T;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        T[i][j] = scale * uniform(random_engine) + (near_identity && i == j);
    return T;
  }

  /// A[i][J][k][L] = A[k][L][i][J], random.
  Tensor4
  random_symmetric_tangent()
  {
    Tensor4 A;
    for (unsigned int a = 0; a < 9; ++a)
      for (unsigned int b = 0; b <= a; ++b)
        {
          const double value            = uniform(random_engine);
          A[a / 3][a % 3][b / 3][b % 3] = value;
          A[b / 3][b % 3][a / 3][a % 3] = value;
        }
    return A;
  }

  struct CellTerms
  {
    Vector<double>     rhs, external, magnitude;
    FullMatrix<double> matrix;
    explicit CellTerms(const unsigned int n)
      : rhs(n)
      , external(n)
      , magnitude(n)
      , matrix(n, n)
    {}
  };

  /// The loop that ElasticCell replaced (forward_problem_assembly.cc).
  void
  plain_loop(const FiniteElement<3>                &fe,
             const FEValues<3>                     &fe_values,
             const std::vector<ElasticCell::Point> &points,
             CellTerms                             &out)
  {
    const unsigned int        n = fe.n_dofs_per_cell();
    std::vector<Tensor<1, 3>> b(n);
    std::vector<Tensor2>      v(n);
    for (const ElasticCell::Point &p : points)
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto [ci, si] = fe.system_to_component_index(i);
            b[i]                = p.G_inv_T * fe_values.shape_grad(si, p.q);
            const double f_ext =
              fe_values.shape_value(si, p.q) * p.f_body[ci] * p.JxW;
            const double f_int = (p.P[ci] * b[i]) * p.dV_rest;
            out.external(i) += f_ext;
            out.rhs(i) += f_ext - f_int;
            out.magnitude(i) += std::abs(f_ext) + std::abs(f_int);
          }
        for (unsigned int j = 0; j < n; ++j)
          {
            const unsigned int cj = fe.system_to_component_index(j).first;
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int K = 0; K < 3; ++K)
                {
                  double sum = 0;
                  for (unsigned int L = 0; L < 3; ++L)
                    sum += (*p.A)[c][K][cj][L] * b[j][L];
                  v[j][c][K] = sum * p.dV_rest;
                }
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int ci = fe.system_to_component_index(i).first;
            for (unsigned int j = 0; j <= i; ++j)
              out.matrix(i, j) += v[j][ci] * b[i];
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        out.matrix(i, j) = out.matrix(j, i);
  }

  double
  largest_difference(const Vector<double> &a, const Vector<double> &b)
  {
    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      d = std::max(d, std::abs(a(i) - b(i)));
    return d;
  }

  double
  largest_difference(const FullMatrix<double> &a, const FullMatrix<double> &b)
  {
    double d = 0;
    for (unsigned int i = 0; i < a.m(); ++i)
      for (unsigned int j = 0; j < a.n(); ++j)
        d = std::max(d, std::abs(a(i, j) - b(i, j)));
    return d;
  }

  void
  check_element(const std::string      &name,
                const Triangulation<3> &mesh,
                const Mapping<3>       &mapping,
                const FiniteElement<3> &scalar,
                const Quadrature<3>    &quadrature)
  {
    const FESystem<3> fe(scalar, 3);
    FEValues<3>       fe_values(mapping,
                          scalar,
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    fe_values.reinit(mesh.begin_active());
    std::vector<Tensor4>            tangents(quadrature.size());
    std::vector<ElasticCell::Point> points;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        tangents[q] = random_symmetric_tangent();
        ElasticCell::Point p;
        p.q       = q;
        p.G_inv_T = random_tensor(0.2, true);
        p.P       = random_tensor(1., false);
        p.A       = &tangents[q];
        p.JxW     = fe_values.JxW(q);
        p.dV_rest = (1 + 0.1 * uniform(random_engine)) * p.JxW;
        for (unsigned int c = 0; c < 3; ++c)
          p.f_body[c] = uniform(random_engine);
        points.push_back(p);
      }
    const unsigned int n = fe.n_dofs_per_cell();
    CellTerms          expected(n), kernel(n), residual_only(n);
    plain_loop(fe, fe_values, points, expected);

    ElasticCell cell(fe);
    cell.reinit(true, 1);
    for (const ElasticCell::Point &p : points)
      cell.add(fe_values, p);
    cell.vectors(kernel.rhs, kernel.external, kernel.magnitude);
    cell.matrix(kernel.matrix);

    check_below(name + ": residual, |difference| (same bits)",
                largest_difference(kernel.rhs, expected.rhs),
                0);
    check_below(name + ": external force, |difference|",
                largest_difference(kernel.external, expected.external),
                0);
    check_below(name + ": magnitudes, |difference|",
                largest_difference(kernel.magnitude, expected.magnitude),
                0);
    check_below(name + ": tangent, |difference|",
                largest_difference(kernel.matrix, expected.matrix),
                0);
    FullMatrix<double> transpose(n, n);
    transpose.copy_transposed(kernel.matrix);
    check_below(name + ": tangent - its transpose",
                largest_difference(kernel.matrix, transpose),
                0);
    check_below(name + ": largest tangent entry > 0 (a test of something)",
                -expected.matrix.linfty_norm(),
                -1e-12);

    // Without the tangent (a residual-only assembly).
    cell.reinit(false, 1);
    for (ElasticCell::Point p : points)
      {
        p.A = nullptr;
        cell.add(fe_values, p);
      }
    cell.vectors(residual_only.rhs,
                 residual_only.external,
                 residual_only.magnitude);
    check_below(name + ": residual without tangent, |difference|",
                largest_difference(residual_only.rhs, expected.rhs),
                0);
  }
} // namespace

int
main()
{
  Triangulation<3> tetrahedron, hexahedron;
  GridGenerator::reference_cell(tetrahedron, ReferenceCells::Tetrahedron);
  GridGenerator::hyper_cube(hexahedron);
  // Skewed cells: their gradients differ from the reference cell's.
  const auto skew = [](const Point<3> &x) {
    return Point<3>(x[0] + 0.3 * x[1],
                    1.2 * x[1] - 0.1 * x[2],
                    x[2] + 0.2 * x[0]);
  };
  GridTools::transform(skew, tetrahedron);
  GridTools::transform(skew, hexahedron);
  const MappingFE<3> simplex_mapping(FE_SimplexP<3>(1));
  const MappingQ<3>  hex_mapping(1);
  for (const unsigned int degree : {1u, 2u})
    {
      check_element("P" + std::to_string(degree),
                    tetrahedron,
                    simplex_mapping,
                    FE_SimplexP<3>(degree),
                    QGaussSimplex<3>(degree + 1));
      check_element("Q" + std::to_string(degree),
                    hexahedron,
                    hex_mapping,
                    FE_Q<3>(degree),
                    QGauss<3>(degree + 1));
    }
  return exit_code();
}
