// SimplexValues against FEValues with MappingFE of FE_SimplexP(1), the
// pair it replaces in the assembly on tetrahedral meshes: on skewed
// tetrahedra of a mesh (P1 and P2, their quadrature rules), the shape
// values, gradients, JxW and quadrature points must be the same to the
// last bit (the same Jacobian, covariant form and products). The same for
// SimplexFaceValues against FEFaceValues on every face of every cell (its
// faces in all the orientations the mesh has), normals included.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <restshape/forward/simplex_face_values.h>
#include <restshape/forward/simplex_values.h>

#include <cmath>
#include <iostream>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  void
  check_degree(const Triangulation<3> &mesh, const unsigned int degree)
  {
    const FE_SimplexP<3>   fe(degree);
    const QGaussSimplex<3> quadrature(degree == 1 ? 1 : degree + 1);
    const MappingFE<3>     mapping(FE_SimplexP<3>(1));
    FEValues<3>            fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients | update_JxW_values |
                            update_quadrature_points);
    SimplexValues          values(fe, quadrature);
    double                 value = 0, gradient = 0, jxw = 0, point = 0;
    double                 largest_gradient = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        fe_values.reinit(cell);
        values.reinit(cell);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            jxw   = std::max(jxw, std::abs(values.JxW(q) - fe_values.JxW(q)));
            point = std::max(point,
                             (values.quadrature_point(q) -
                              fe_values.quadrature_point(q))
                               .norm());
            for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
              {
                value    = std::max(value,
                                 std::abs(values.shape_value(k, q) -
                                          fe_values.shape_value(k, q)));
                gradient = std::max(gradient,
                                    (values.shape_grad(k, q) -
                                     fe_values.shape_grad(k, q))
                                      .norm());
                largest_gradient =
                  std::max(largest_gradient, fe_values.shape_grad(k, q).norm());
              }
          }
      }
    const std::string name = "P" + std::to_string(degree);
    check_below(name + ": shape values, |difference|", value, 0);
    check_below(name + ": shape gradients, |difference|", gradient, 0);
    check_below(name + ": JxW, |difference|", jxw, 0);
    check_below(name + ": quadrature points, |difference|", point, 0);
    check_below(name + ": gradients > 1 on cells < 1 (a test of something)",
                -largest_gradient,
                -1);
  }

  void
  check_faces(const Triangulation<3> &mesh, const unsigned int degree)
  {
    const FE_SimplexP<3>   fe(degree);
    const QGaussSimplex<2> quadrature(degree + 1);
    const MappingFE<3>     mapping(FE_SimplexP<3>(1));
    FEFaceValues<3>        fe_values(mapping,
                              fe,
                              quadrature,
                              update_values | update_gradients |
                                update_JxW_values | update_quadrature_points |
                                update_normal_vectors);
    SimplexFaceValues      values(fe, quadrature);
    double       value = 0, gradient = 0, jxw = 0, point = 0, normal = 0;
    double       area   = 0;
    unsigned int turned = 0; // faces not in the standard orientation
    for (const auto &cell : mesh.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          fe_values.reinit(cell, f);
          values.reinit(cell, f);
          turned += !cell->face_orientation(f) || cell->face_flip(f) ||
                    cell->face_rotation(f);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              jxw = std::max(jxw, std::abs(values.JxW(q) - fe_values.JxW(q)));
              area += values.JxW(q);
              point  = std::max(point,
                               (values.quadrature_point(q) -
                                fe_values.quadrature_point(q))
                                 .norm());
              normal = std::max(
                normal,
                (values.normal_vector(q) - fe_values.normal_vector(q)).norm());
              for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
                {
                  value    = std::max(value,
                                   std::abs(values.shape_value(k, q) -
                                            fe_values.shape_value(k, q)));
                  gradient = std::max(gradient,
                                      (values.shape_grad(k, q) -
                                       fe_values.shape_grad(k, q))
                                        .norm());
                }
            }
        }
    const std::string name = "P" + std::to_string(degree) + " faces";
    check_below(name + ": shape values, |difference|", value, 0);
    check_below(name + ": shape gradients, |difference|", gradient, 0);
    check_below(name + ": JxW, |difference|", jxw, 0);
    check_below(name + ": quadrature points, |difference|", point, 0);
    check_below(name + ": normals, |difference|", normal, 0);
    check_below(name + ": area > 0 (a test of something)", -area, -1e-3);
    check_below(name + ": faces in other orientations (of every kind)",
                -double(turned),
                -1);
  }
} // namespace

int
main()
{
  // A subdivided, skewed and twisted box of tetrahedra.
  Triangulation<3> hexahedra, mesh;
  GridGenerator::subdivided_hyper_cube(hexahedra, 2, 0., 0.5);
  GridGenerator::convert_hypercube_to_simplex_mesh(hexahedra, mesh);
  GridTools::transform(
    [](const Point<3> &x) {
      return Point<3>(x[0] + 0.3 * x[1] * x[2],
                      1.2 * x[1] - 0.1 * x[2] + 0.05 * x[0] * x[0],
                      x[2] + 0.2 * x[0] + 1e-3);
    },
    mesh);
  for (const unsigned int degree : {1u, 2u})
    {
      check_degree(mesh, degree);
      check_faces(mesh, degree);
    }
  return exit_code();
}
