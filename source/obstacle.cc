#include <restshape/input_error.h>
#include <restshape/obstacle.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <filesystem>
#include <unistd.h>

namespace RestShape
{
  namespace
  {
    using Kernel    = CGAL::Exact_predicates_inexact_constructions_kernel;
    using CPoint    = Kernel::Point_3;
    using Mesh      = CGAL::Surface_mesh<CPoint>;
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
    using Tree      = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
    namespace PMP   = CGAL::Polygon_mesh_processing;
    const std::string parameter = "Contact/Obstacle file";
  } // namespace

  struct Obstacle::Data
  {
    Mesh                                         mesh;
    std::unique_ptr<Tree>                        tree;
    std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side;
  };

  Obstacle::Obstacle(const std::string &file, const double length_unit, const bool inside)
    : data(std::make_unique<Data>())
    , inside(inside)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec) || ::access(file.c_str(), R_OK) != 0)
      throw InputError(file, parameter, "no such readable file; expected a closed triangulated surface (.stl, .off or .obj)");
    const std::string extension = fs::path(file).extension().string();
    if (extension != ".stl" && extension != ".off" && extension != ".obj" &&
        extension != ".STL" && extension != ".OFF" && extension != ".OBJ")
      throw InputError(file, parameter,
                       "unsupported format '" + extension + "'; expected .stl, .off or .obj");

    // The PMP reader repairs polygon soups (STL stores every triangle with
    // its own vertices) and orients them consistently; the global
    // orientation is checked below.
    Mesh &mesh = data->mesh;
    bool  ok   = false;
    try
      {
        ok = PMP::IO::read_polygon_mesh(file, mesh);
      }
    catch (...)
      {
        ok = false;
      }
    if (!ok || mesh.number_of_faces() == 0)
      throw InputError(file, parameter,
                       "cannot be read as a polygon surface (or it is not 2-manifold)");
    if (!CGAL::is_triangle_mesh(mesh))
      PMP::triangulate_faces(mesh);
    if (!CGAL::is_closed(mesh))
      throw InputError(file, parameter,
                       "the surface is open (it has border edges); expected a closed surface");
    if (PMP::does_self_intersect(mesh))
      throw InputError(file, parameter, "the surface intersects itself");
    if (!PMP::is_outward_oriented(mesh))
      throw InputError(file, parameter,
                       "the surface is oriented inward (flipped normals); expected "
                       "normals pointing out of the enclosed region");
    for (const auto v : mesh.vertices())
      {
        const CPoint &p = mesh.point(v);
        mesh.point(v)   = CPoint(p.x() * length_unit, p.y() * length_unit, p.z() * length_unit);
      }

    data->tree = std::make_unique<Tree>(faces(mesh).first, faces(mesh).second, mesh);
    data->tree->accelerate_distance_queries();
    data->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(*data->tree);
  }

  Obstacle::~Obstacle() = default;

  Gap
  Obstacle::gap(const dealii::Point<3> &x) const
  {
    const CPoint p(x[0], x[1], x[2]);
    const auto [closest, face] = data->tree->closest_point_and_primitive(p);
    const CGAL::Bounded_side position = (*data->side)(p);
    const bool allowed = inside ? position != CGAL::ON_UNBOUNDED_SIDE :
                                  position != CGAL::ON_BOUNDED_SIDE;
    const dealii::Tensor<1, 3> to_point({p.x() - closest.x(), p.y() - closest.y(), p.z() - closest.z()});
    const double distance = to_point.norm();

    Gap result;
    result.gap = allowed ? distance : -distance;
    // The gradient of the signed distance; on (or very near) the surface,
    // the normal of the closest face, oriented to the allowed side.
    const auto n = PMP::compute_face_normal(face, data->mesh);
    dealii::Tensor<1, 3> face_normal({n.x(), n.y(), n.z()});
    if (inside)
      face_normal *= -1;
    if (distance > 1e-12 * std::max(1., std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2])))
      result.normal = (allowed ? 1. : -1.) * to_point / distance;
    else
      result.normal = face_normal;
    return result;
  }

  unsigned int
  Obstacle::n_crossings(const dealii::Point<3> &a, const dealii::Point<3> &b) const
  {
    if (a.distance(b) == 0)
      return 0;
    const Kernel::Segment_3 segment(CPoint(a[0], a[1], a[2]), CPoint(b[0], b[1], b[2]));
    return data->tree->number_of_intersected_primitives(segment);
  }

  unsigned int
  Obstacle::n_triangles() const
  {
    return data->mesh.number_of_faces();
  }
} // namespace RestShape
