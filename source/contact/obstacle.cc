#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <restshape/base/child_process.h>
#include <restshape/base/input_error.h>
#include <restshape/contact/obstacle.h>
#include <restshape/contact/off_faces.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

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
    Mesh                                                       mesh;
    std::unique_ptr<Tree>                                      tree;
    std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side;
    /// Per face, the smoothed normals at its three corners (see gap()).
    std::vector<std::array<dealii::Tensor<1, 3>, 3>> corner_normals;
  };

  namespace
  {
    dealii::Tensor<1, 3>
    tensor(const Kernel::Vector_3 &v)
    {
      return dealii::Tensor<1, 3>({v.x(), v.y(), v.z()});
    }

    /// Outward normal at every corner of every face: the area-weighted mean
    /// of the normals of the faces around that vertex that lie within
    /// `feature_angle` of the face's own normal. Across smooth parts (a
    /// skull) the normal field becomes continuous; sharp edges (a box)
    /// stay sharp.
    std::vector<std::array<dealii::Tensor<1, 3>, 3>>
    smoothed_corner_normals(const Mesh &mesh, const double feature_angle)
    {
      std::vector<dealii::Tensor<1, 3>> area_normal(mesh.number_of_faces());
      for (const auto f : mesh.faces())
        {
          std::vector<CPoint> c;
          for (const auto v :
               CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            c.push_back(mesh.point(v));
          area_normal[f.idx()] =
            0.5 * tensor(CGAL::cross_product(c[1] - c[0], c[2] - c[0]));
        }
      const double cos_feature = std::cos(feature_angle);
      std::vector<std::array<dealii::Tensor<1, 3>, 3>> result(
        mesh.number_of_faces());
      for (const auto f : mesh.faces())
        {
          const dealii::Tensor<1, 3> own =
            area_normal[f.idx()] / area_normal[f.idx()].norm();
          unsigned int corner = 0;
          for (const auto v :
               CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            {
              dealii::Tensor<1, 3> sum;
              for (const auto g :
                   CGAL::faces_around_target(mesh.halfedge(v), mesh))
                if (g != Mesh::null_face() &&
                    area_normal[g.idx()] * own >=
                      cos_feature * area_normal[g.idx()].norm())
                  sum += area_normal[g.idx()];
              result[f.idx()][corner++] = sum / sum.norm();
            }
        }
      return result;
    }
  } // namespace

  namespace
  {
    /**
     * Read @p file as a polygon soup, check it (CGAL's OBJ reader takes
     * any face index: 0 or one past the last vertex crashed the repair
     * that follows), repair it (STL stores every triangle with its own
     * vertices), orient it consistently (the global orientation is
     * checked by the caller) and make it a surface mesh.
     */
    void
    read_surface(const std::string &file, Mesh &mesh)
    {
      std::vector<CPoint>                   points;
      std::vector<std::vector<std::size_t>> polygons;
      bool                                  ok = false;
      check_off_faces(file, parameter);
      try
        {
          ok = CGAL::IO::read_polygon_soup(file, points, polygons);
        }
      catch (...)
        {
          ok = false;
        }
      const auto fail = [&](const std::string &what) {
        throw InputError(file, parameter, what);
      };
      if (!ok || polygons.empty())
        fail("cannot be read as a polygon surface; expected a closed "
             "triangulated surface");
      for (const CPoint &p : points)
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()) ||
            !std::isfinite(p.z()))
          fail("a vertex has a coordinate that is not a finite number");
      for (std::size_t f = 0; f < polygons.size(); ++f)
        {
          if (polygons[f].size() < 3)
            fail("face " + std::to_string(f + 1) +
                 " has fewer than 3 vertices");
          for (const std::size_t v : polygons[f])
            if (v >= points.size())
              fail("face " + std::to_string(f + 1) +
                   " refers to a vertex that does not exist (the file has " +
                   std::to_string(points.size()) + " vertices)");
        }
      PMP::repair_polygon_soup(points, polygons);
      if (!PMP::orient_polygon_soup(points, polygons) || polygons.empty())
        fail("cannot be read as a polygon surface (it is not 2-manifold)");
      PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
      if (mesh.number_of_faces() == 0)
        fail("cannot be read as a polygon surface (it has no face)");
    }

    /// Read, triangulate and check the closed surface in @p file.
    void
    read_closed_surface(const std::string &file, Mesh &mesh)
    {
      read_surface(file, mesh);
      if (!CGAL::is_triangle_mesh(mesh))
        PMP::triangulate_faces(mesh);
      if (!CGAL::is_closed(mesh))
        throw InputError(
          file,
          parameter,
          "the surface is open (it has border edges); expected a closed "
          "surface");
      if (PMP::does_self_intersect(mesh))
        throw InputError(file, parameter, "the surface intersects itself");
      if (!PMP::is_outward_oriented(mesh))
        throw InputError(
          file,
          parameter,
          "the surface is oriented inward (flipped normals); expected "
          "normals pointing out of the enclosed region");
    }

    /// The triangles of @p mesh: its points, then its vertex triples.
    std::string
    triangle_soup(Mesh &mesh)
    {
      mesh.collect_garbage();
      ByteWriter out;
      out.put<std::uint64_t>(mesh.number_of_vertices());
      for (const auto v : mesh.vertices())
        for (unsigned int d = 0; d < 3; ++d)
          out.put<double>(mesh.point(v)[d]);
      out.put<std::uint64_t>(mesh.number_of_faces());
      for (const auto f : mesh.faces())
        for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
          out.put<std::uint64_t>(v);
      return out.str();
    }

    /// The mesh of a triangle soup made by triangle_soup().
    void
    mesh_of_triangle_soup(ByteReader &in, Mesh &mesh)
    {
      std::vector<CPoint> points(in.checked_count(24));
      for (CPoint &p : points)
        {
          const double x = in.get<double>(), y = in.get<double>();
          p = CPoint(x, y, in.get<double>());
        }
      std::vector<std::array<std::size_t, 3>> triangles(in.checked_count(24));
      for (auto &t : triangles)
        for (std::size_t &v : t)
          {
            v = in.get<std::uint64_t>();
            if (v >= points.size())
              throw std::runtime_error("a vertex index out of range");
          }
      PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
    }
  } // namespace

  Obstacle::Obstacle(const std::string &file,
                     const double       length_unit,
                     const bool         inside)
    : data(std::make_unique<Data>())
    , inside(inside)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec) || ::access(file.c_str(), R_OK) != 0)
      throw InputError(
        file,
        parameter,
        "no such readable file; expected a closed triangulated surface (.stl, .off or .obj)");
    const std::string extension = fs::path(file).extension().string();
    if (extension != ".stl" && extension != ".off" && extension != ".obj" &&
        extension != ".STL" && extension != ".OFF" && extension != ".OBJ")
      throw InputError(file,
                       parameter,
                       "unsupported format '" + extension +
                         "'; expected .stl, .off or .obj");

    // CGAL's readers and face triangulation run in a child process: on
    // some malformed files they reach undefined behaviour (found by
    // fuzzing); only checked triangles come back.
    Mesh &mesh = data->mesh;
    run_in_child_process(
      [&file]() {
        Mesh surface;
        read_closed_surface(file, surface);
        return triangle_soup(surface);
      },
      [&mesh](ByteReader &in) { mesh_of_triangle_soup(in, mesh); },
      file,
      parameter,
      "a closed triangulated surface");
    for (const auto v : mesh.vertices())
      {
        const CPoint &p = mesh.point(v);
        mesh.point(v) =
          CPoint(p.x() * length_unit, p.y() * length_unit, p.z() * length_unit);
      }

    data->tree =
      std::make_unique<Tree>(faces(mesh).first, faces(mesh).second, mesh);
    data->tree->accelerate_distance_queries();
    data->side =
      std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(*data->tree);
    data->corner_normals = smoothed_corner_normals(mesh, 30. * M_PI / 180.);
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
    const dealii::Tensor<1, 3> to_point(
      {p.x() - closest.x(), p.y() - closest.y(), p.z() - closest.z()});
    const double distance = to_point.norm();

    Gap result;
    result.gap = allowed ? distance : -distance;
    // The normal: the smoothed (Phong) normal at the closest point, i.e. the
    // barycentric interpolation of the face's corner normals. A piecewise
    // flat skull has a normal that jumps across every edge; a node resting
    // in a crease between two faces then flips between them and the active
    // set never settles. The interpolated field is continuous over smooth
    // parts of the surface (the faces around a vertex within 30 degrees of
    // each other) and keeps sharp edges sharp, so flat obstacles and boxes
    // get their exact face normals.
    std::vector<CPoint> c;
    for (const auto v :
         CGAL::vertices_around_face(data->mesh.halfedge(face), data->mesh))
      c.push_back(data->mesh.point(v));
    const auto   n_face = CGAL::cross_product(c[1] - c[0], c[2] - c[0]);
    const double area2  = n_face.squared_length();
    std::array<double, 3> weight;
    for (unsigned int i = 0; i < 3; ++i)
      weight[i] = std::max(0.,
                           CGAL::cross_product(c[(i + 2) % 3] - c[(i + 1) % 3],
                                               closest - c[(i + 1) % 3]) *
                             n_face / area2);
    const auto          &corners = data->corner_normals[face.idx()];
    dealii::Tensor<1, 3> normal =
      weight[0] * corners[0] + weight[1] * corners[1] + weight[2] * corners[2];
    if (normal.norm() < 1e-12)
      normal = tensor(n_face);
    // Corner normals point out of the enclosed region.
    const double to_allowed = inside ? -1. : 1.;
    result.normal           = to_allowed * normal / normal.norm();
    const dealii::Tensor<1, 3> face_normal = tensor(n_face) / std::sqrt(area2);
    result.gradient =
      distance > 1e-9 * std::sqrt(area2) ?
        dealii::Tensor<1, 3>((allowed ? 1. : -1.) * to_point / distance) :
        to_allowed * face_normal;
    return result;
  }

  unsigned int
  Obstacle::n_crossings(const dealii::Point<3> &a,
                        const dealii::Point<3> &b) const
  {
    if (a.distance(b) == 0)
      return 0;
    const Kernel::Segment_3 segment(CPoint(a[0], a[1], a[2]),
                                    CPoint(b[0], b[1], b[2]));
    return data->tree->number_of_intersected_primitives(segment);
  }

  unsigned int
  Obstacle::n_triangles() const
  {
    return data->mesh.number_of_faces();
  }

  std::vector<dealii::Point<3>>
  Obstacle::vertices() const
  {
    std::vector<dealii::Point<3>> points;
    for (const auto v : data->mesh.vertices())
      {
        const auto &p = data->mesh.point(v);
        points.emplace_back(CGAL::to_double(p.x()),
                            CGAL::to_double(p.y()),
                            CGAL::to_double(p.z()));
      }
    return points;
  }

  std::pair<dealii::Point<3>, dealii::Point<3>>
  Obstacle::bounding_box() const
  {
    const auto box = data->tree->bbox();
    return {dealii::Point<3>(box.xmin(), box.ymin(), box.zmin()),
            dealii::Point<3>(box.xmax(), box.ymax(), box.zmax())};
  }
} // namespace RestShape
