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

#include <restshape/fem/simplex_face_values.h>
#include <restshape/fem/simplex_values.h>

#include <cmath>
#include <iostream>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  /// The largest differences between ours and deal.II's values on the
  /// cells or faces seen so far.
  struct Differences
  {
    double value = 0, gradient = 0, jxw = 0, point = 0;
    double largest_gradient = 0; // of deal.II's

    /// Compare at every point of the current cell or face.
    template <typename Ours, typename Theirs>
    void
    add(const Ours &ours, const Theirs &theirs, const unsigned int n_dofs)
    {
      for (unsigned int q = 0; q < theirs.n_quadrature_points; ++q)
        {
          jxw   = std::max(jxw, std::abs(ours.JxW(q) - theirs.JxW(q)));
          point = std::max(
            point,
            (ours.quadrature_point(q) - theirs.quadrature_point(q)).norm());
          for (unsigned int k = 0; k < n_dofs; ++k)
            {
              value    = std::max(value,
                               std::abs(ours.shape_value(k, q) -
                                        theirs.shape_value(k, q)));
              gradient = std::max(
                gradient,
                (ours.shape_grad(k, q) - theirs.shape_grad(k, q)).norm());
              largest_gradient =
                std::max(largest_gradient, theirs.shape_grad(k, q).norm());
            }
        }
    }

    void
    check(const std::string &name) const
    {
      check_below(name + ": shape values, |difference|", value, 0);
      check_below(name + ": shape gradients, |difference|", gradient, 0);
      check_below(name + ": JxW, |difference|", jxw, 0);
      check_below(name + ": quadrature points, |difference|", point, 0);
    }
  };

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
    Differences            differences;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        fe_values.reinit(cell);
        values.reinit(cell);
        differences.add(values, fe_values, fe.n_dofs_per_cell());
      }
    const std::string name = "P" + std::to_string(degree);
    differences.check(name);
    check_below(name + ": gradients > 1 on cells < 1 (a test of something)",
                -differences.largest_gradient,
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
    Differences            differences;
    double                 normal = 0, area = 0;
    unsigned int           turned = 0; // faces not in the standard orientation
    for (const auto &cell : mesh.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          fe_values.reinit(cell, f);
          values.reinit(cell, f);
          turned += !cell->face_orientation(f) || cell->face_flip(f) ||
                    cell->face_rotation(f);
          differences.add(values, fe_values, fe.n_dofs_per_cell());
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              area += values.JxW(q);
              normal = std::max(
                normal,
                (values.normal_vector(q) - fe_values.normal_vector(q)).norm());
            }
        }
    const std::string name = "P" + std::to_string(degree) + " faces";
    differences.check(name);
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
