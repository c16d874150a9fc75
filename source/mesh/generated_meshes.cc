#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <restshape/mesh/generated_meshes.h>

namespace RestShape
{
  using namespace dealii;

  void
  make_hemisphere(Triangulation<3>  &tria,
                  const double       radius,
                  const unsigned int refinements,
                  const double       grading)
  {
    Triangulation<3> ball;
    GridGenerator::half_hyper_ball(ball, Point<3>(), radius);
    ball.refine_global(refinements);
    // Flatten to a plain coarse mesh (no manifold, no hierarchy).
    std::vector<Point<3>>    vertices = ball.get_vertices();
    std::vector<CellData<3>> cells;
    for (const auto &cell : ball.active_cell_iterators())
      {
        CellData<3> c(8);
        for (unsigned int v = 0; v < 8; ++v)
          c.vertices[v] = cell->vertex_index(v);
        cells.push_back(c);
      }
    // Rotate x -> -z (dome down) and lift the pole to the origin.
    const Point<3> center(0, 0, radius);
    for (Point<3> &p : vertices)
      p = Point<3>(p[2], p[1], -p[0]) + Tensor<1, 3>(center);

    // Grade towards the pole (r -> r_max (r / r_max)^grading at the pole);
    // keep the curved surface on the sphere.
    double r_max = 0;
    for (const Point<3> &p : vertices)
      r_max = std::max(r_max, p.norm());
    for (Point<3> &p : vertices)
      {
        const bool on_sphere =
          std::abs(p.distance(center) - radius) < 1e-9 * radius &&
          p[2] < radius * (1 - 1e-9);
        // The scale along the ray from the pole fades out towards the top,
        // which stays a plane.
        const double r = p.norm();
        if (r > 0)
          p *= std::pow(std::pow(r / r_max, grading - 1), 1 - p[2] / radius);
        if (on_sphere)
          p = center + radius * (p - center) / p.distance(center);
      }
    tria.clear();
    tria.create_triangulation(vertices, cells, SubCellData());
    for (const auto &cell : tria.active_cell_iterators())
      {
        unsigned int on_top = 0;
        for (const unsigned int v : cell->vertex_indices())
          on_top += cell->vertex(v)[2] > radius * (1 - 1e-9);
        cell->set_material_id(on_top >= 4 ? 2 : 1);
      }
  }
} // namespace RestShape
