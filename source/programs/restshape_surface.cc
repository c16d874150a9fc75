// restshape-surface: closed triangulated surfaces for obstacles in tests and
// benchmarks (CGAL), outward oriented unless --flip.
//
//   restshape-surface --box X0,Y0,Z0 --size LX,LY,LZ --out FILE
//   restshape-surface --sphere X,Y,Z --radius R [--subdivisions N] --out FILE
//       [--flip] [--open]
//
// FILE: .off, .stl or .obj. --flip reverses every face (an inward-oriented
// surface), --open deletes one face (a surface with a hole): both make
// invalid obstacles, for the error tests.
#include <deal.II/base/utilities.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>
#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/interruption.h>
#include <restshape/base/version.h>

#include <array>
#include <iostream>
#include <string>

namespace
{
  /// --help: the usage comment at the top of this file.
  const char *const usage =
    "restshape-surface: closed triangulated surfaces for obstacles in tests and\n"
    "benchmarks (CGAL), outward oriented unless --flip.\n"
    "\n"
    "  restshape-surface --box X0,Y0,Z0 --size LX,LY,LZ --out FILE\n"
    "  restshape-surface --sphere X,Y,Z --radius R [--subdivisions N] --out FILE\n"
    "      [--flip] [--open]\n"
    "\n"
    "FILE: .off, .stl or .obj. --flip reverses every face (an inward-oriented\n"
    "surface), --open deletes one face (a surface with a hole): both make\n"
    "invalid obstacles, for the error tests.\n";
} // namespace

using namespace RestShape;

namespace
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point  = Kernel::Point_3;
  using Mesh   = CGAL::Surface_mesh<Point>;

} // namespace

int
main(int argc, char **argv)
{
  RestShape::install_interrupt_handlers();
  try
    {
      const ToolOptions cl(
        argc,
        argv,
        {"--box", "--sphere", "--size", "--radius", "--subdivisions", "--out"},
        {"--flip", "--open"});
      if (cl.version())
        {
          std::cout << version_text("restshape-surface") << std::endl;
          return 0;
        }
      if (cl.help())
        {
          std::cout << usage;
          return 0;
        }
      if (cl.given("--box") == cl.given("--sphere"))
        throw InputError("",
                         "--box",
                         "expected either --box X0,Y0,Z0 or --sphere X,Y,Z");
      const std::string           shape  = cl.given("--box") ? "box" : "sphere";
      const std::array<double, 3> a      = cl.triple("--" + shape, {{0, 0, 0}});
      const std::array<double, 3> size   = cl.triple("--size", {{1, 1, 1}});
      const double                radius = cl.positive("--radius", 1);
      const unsigned int subdivisions = cl.integer("--subdivisions", 3, 0, 8);
      const bool         flip         = cl.given("--flip");
      const bool         open         = cl.given("--open");
      const std::string  out = cl.required("--out", "a surface file name");

      Mesh mesh;
      if (shape == "box")
        {
          const double x0 = a[0], y0 = a[1], z0 = a[2];
          const double x1 = x0 + size[0], y1 = y0 + size[1], z1 = z0 + size[2];
          CGAL::make_hexahedron(Point(x0, y0, z0),
                                Point(x1, y0, z0),
                                Point(x1, y1, z0),
                                Point(x0, y1, z0),
                                Point(x0, y1, z1),
                                Point(x0, y0, z1),
                                Point(x1, y0, z1),
                                Point(x1, y1, z1),
                                mesh);
          CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
        }
      else
        {
          CGAL::make_icosahedron(mesh, Point(a[0], a[1], a[2]), radius);
          CGAL::Subdivision_method_3::Loop_subdivision(
            mesh, CGAL::parameters::number_of_iterations(subdivisions));
          for (const auto v : mesh.vertices())
            {
              const auto d  = mesh.point(v) - Point(a[0], a[1], a[2]);
              mesh.point(v) = Point(a[0], a[1], a[2]) +
                              d * (radius / std::sqrt(d.squared_length()));
            }
        }
      if (!CGAL::Polygon_mesh_processing::is_outward_oriented(mesh))
        CGAL::Polygon_mesh_processing::reverse_face_orientations(mesh);
      if (flip)
        CGAL::Polygon_mesh_processing::reverse_face_orientations(mesh);
      if (open)
        {
          CGAL::Euler::remove_face(halfedge(*mesh.faces().begin(), mesh), mesh);
          mesh.collect_garbage();
        }
      if (!CGAL::IO::write_polygon_mesh(out,
                                        mesh,
                                        CGAL::parameters::stream_precision(17)))
        throw InputError(out, "--out", "cannot write the surface");
      std::cout << out << ": " << mesh.number_of_faces() << " triangles"
                << std::endl;
    }
  catch (const std::exception &exc)
    {
      std::cerr << "restshape-surface: error: " << one_line_message(exc)
                << std::endl;
      return 1;
    }
  return 0;
}
