// SimplexValues: FEValues of a scalar element on affine tetrahedra.
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/grid_generator.h>

#include <restshape/fem/simplex_values.h>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    constexpr unsigned int n_vertices = 4;
  } // namespace

  SimplexValues::SimplexValues(const FiniteElement<3> &fe,
                               const Quadrature<3>    &quadrature)
    : n_quadrature_points(quadrature.size())
    , dofs_per_cell(fe.n_dofs_per_cell())
    , weights(quadrature.get_weights())
    , values(dofs_per_cell * n_quadrature_points)
    , reference_gradients(values.size())
    , vertex_shapes(n_quadrature_points * n_vertices)
    , gradients(values.size())
    , JxW_values(n_quadrature_points)
    , points(n_quadrature_points)
  {
    AssertThrow(fe.reference_cell() == ReferenceCells::Tetrahedron,
                ExcMessage("SimplexValues: expected a tetrahedral element"));
    // The reference cell's data as FEValues has it: its Jacobian is the
    // identity, so its gradients are the element's before the mapping.
    Triangulation<3> reference;
    GridGenerator::reference_cell(reference, ReferenceCells::Tetrahedron);
    const FE_SimplexP<3> linear(1);
    const MappingFE<3>   mapping(linear);
    FEValues<3>          fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients);
    fe_values.reinit(reference.begin_active());
    for (unsigned int k = 0; k < dofs_per_cell; ++k)
      for (unsigned int q = 0; q < n_quadrature_points; ++q)
        {
          values[k * n_quadrature_points + q] = fe_values.shape_value(k, q);
          reference_gradients[k * n_quadrature_points + q] =
            fe_values.shape_grad(k, q);
        }
    // The linear element's values at the points, as MappingFE evaluates
    // them (its polynomial space's evaluate()).
    std::vector<double>             shapes(n_vertices);
    std::vector<Tensor<1, 3>>       unused_1;
    std::vector<Tensor<2, 3>>       unused_2;
    std::vector<Tensor<3, 3>>       unused_3;
    std::vector<Tensor<4, 3>>       unused_4;
    const ScalarPolynomialsBase<3> &space = linear.get_poly_space();
    for (unsigned int q = 0; q < n_quadrature_points; ++q)
      {
        space.evaluate(
          quadrature.point(q), shapes, unused_1, unused_2, unused_3, unused_4);
        for (unsigned int v = 0; v < n_vertices; ++v)
          vertex_shapes[q * n_vertices + v] = shapes[v];
      }
  }

  SimplexValues::SimplexValues(const SimplexValues &all,
                               const unsigned int   start,
                               const unsigned int   n)
    : n_quadrature_points(n)
    , dofs_per_cell(all.dofs_per_cell)
    , weights(all.weights.begin() + start, all.weights.begin() + start + n)
    , values(dofs_per_cell * n)
    , reference_gradients(values.size())
    , vertex_shapes(all.vertex_shapes.begin() + start * n_vertices,
                    all.vertex_shapes.begin() + (start + n) * n_vertices)
    , gradients(values.size())
    , JxW_values(n)
    , points(n)
  {
    AssertThrow(start + n <= all.n_quadrature_points, ExcInternalError());
    for (unsigned int k = 0; k < dofs_per_cell; ++k)
      for (unsigned int q = 0; q < n; ++q)
        {
          const unsigned int from = k * all.n_quadrature_points + start + q;
          values[k * n + q]       = all.values[from];
          reference_gradients[k * n + q] = all.reference_gradients[from];
        }
  }

  void
  SimplexValues::reinit(const Triangulation<3>::cell_iterator &cell)
  {
    // The Jacobian of x = sum_v X_v phi_v(xi): column j is X_(j+1) - X_0
    // (the linear shape functions' gradients are -1 and the unit vectors).
    Point<3> X[n_vertices];
    vertex_mean = Point<3>();
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        X[v] = cell->vertex(v);
        vertex_mean += X[v];
      }
    vertex_mean /= n_vertices;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        J[i][j] = -X[0][i] + X[j + 1][i];
    const DerivativeForm<1, 3, 3> covariant = J.covariant_form();
    const double                  det       = J.determinant();
    for (unsigned int q = 0; q < n_quadrature_points; ++q)
      {
        JxW_values[q]        = weights[q] * det;
        const double *shapes = &vertex_shapes[q * n_vertices];
        Point<3>      x      = shapes[0] * X[0];
        for (unsigned int v = 1; v < n_vertices; ++v)
          for (unsigned int i = 0; i < 3; ++i)
            x[i] += shapes[v] * X[v][i];
        points[q] = x;
      }
    for (unsigned int r = 0; r < gradients.size(); ++r)
      gradients[r] = apply_transformation(covariant, reference_gradients[r]);
  }
} // namespace RestShape
