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
    double                                       size = 0; // bounding-box diagonal
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
    const auto box = data->tree->bbox();
    data->size     = std::sqrt(std::pow(box.xmax() - box.xmin(), 2) +
                           std::pow(box.ymax() - box.ymin(), 2) +
                           std::pow(box.zmax() - box.zmin(), 2));
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
    // The gradient of the signed distance. On (or very near) the surface,
    // where the direction to the closest point is round-off noise, the
    // pseudo-normal: the sum of the distinct normals of all faces as close
    // as the closest one (one face inside a facet; two on an edge, three at
    // a corner), which does not flip between faces with round-off.
    const double tolerance = 1e-8 * data->size;
    if (distance > tolerance)
      {
        result.normal = (allowed ? 1. : -1.) * to_point / distance;
        return result;
      }
    std::vector<Primitive::Id> near;
    const CGAL::Bbox_3 box(p.x() - 2 * tolerance, p.y() - 2 * tolerance, p.z() - 2 * tolerance,
                           p.x() + 2 * tolerance, p.y() + 2 * tolerance, p.z() + 2 * tolerance);
    data->tree->all_intersected_primitives(box, std::back_inserter(near));
    if (near.empty())
      near.push_back(face);
    std::vector<dealii::Tensor<1, 3>> normals;
    for (const auto f : near)
      {
        std::vector<CPoint> corners;
        for (const auto v : CGAL::vertices_around_face(data->mesh.halfedge(f), data->mesh))
          corners.push_back(data->mesh.point(v));
        const Kernel::Triangle_3 t(corners[0], corners[1], corners[2]);
        if (std::sqrt(CGAL::squared_distance(t, p)) > distance + tolerance)
          continue;
        const auto           n = PMP::compute_face_normal(f, data->mesh);
        dealii::Tensor<1, 3> normal({n.x(), n.y(), n.z()});
        bool                 known = false;
        for (const auto &m : normals)
          known = known || (m - normal).norm() < 1e-10;
        if (!known)
          normals.push_back(normal);
      }
    dealii::Tensor<1, 3> sum;
    for (const auto &n : normals)
      sum += n;
    if (sum.norm() < 1e-12)
      {
        const auto n = PMP::compute_face_normal(face, data->mesh);
        sum          = dealii::Tensor<1, 3>({n.x(), n.y(), n.z()});
      }
    result.normal = (inside ? -1. : 1.) * sum / sum.norm();
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
