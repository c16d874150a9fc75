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
  if (wants_help(argc, argv))
    {
      std::cout << usage;
      return 0;
    }
  try
    {
      std::string           shape, out;
      std::array<double, 3> a{{0, 0, 0}}, size{{1, 1, 1}};
      double                radius       = 1;
      unsigned int          subdivisions = 3;
      bool                  flip = false, open = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--flip")
            flip = true;
          else if (arg == "--open")
            open = true;
          else if (i + 1 >= argc)
            throw std::runtime_error("missing value after " + arg);
          else if (arg == "--box" || arg == "--sphere")
            {
              shape = arg.substr(2);
              a     = parse_triple(arg, argv[++i]);
            }
          else if (arg == "--size")
            size = parse_triple(arg, argv[++i]);
          else if (arg == "--radius")
            radius = parse_positive(arg, argv[++i]);
          else if (arg == "--subdivisions")
            subdivisions = std::stoi(argv[++i]);
          else if (arg == "--out")
            out = argv[++i];
          else
            throw std::runtime_error("unknown option " + arg);
        }
      if (shape.empty() || out.empty())
        throw std::runtime_error(
          "usage: restshape-surface --box X,Y,Z --size LX,LY,LZ | "
          "--sphere X,Y,Z --radius R [--subdivisions N] --out FILE");

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
        throw std::runtime_error("cannot write " + out);
      std::cout << out << ": " << mesh.number_of_faces() << " triangles"
                << std::endl;
    }
  catch (const std::exception &exc)
    {
      std::cerr << "restshape-surface: error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
