#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <restshape/mesh/mesh_description.h>
#include <restshape/mesh/mesh_pieces.h>
#include <restshape/mesh/mesh_transforms.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// Local vertex numbers of the faces of a tetrahedron and of a
    /// hexahedron (deal.II's lexicographic vertex order).
    const std::vector<std::vector<unsigned int>> tet_faces = {{0, 1, 2},
                                                              {0, 1, 3},
                                                              {0, 2, 3},
                                                              {1, 2, 3}};
    const std::vector<std::vector<unsigned int>> hex_faces = {{0, 2, 4, 6},
                                                              {1, 3, 5, 7},
                                                              {0, 1, 4, 5},
                                                              {2, 3, 6, 7},
                                                              {0, 1, 2, 3},
                                                              {4, 5, 6, 7}};

    /// Every face of the cells of @p mesh, as its sorted vertex numbers
    /// (unused entries the largest number), with the cells that have it and
    /// the face's number in each of them.
    std::map<std::array<unsigned int, 4>,
             std::vector<std::pair<unsigned int, unsigned int>>>
    faces_of(const MeshDescription &mesh)
    {
      std::map<std::array<unsigned int, 4>,
               std::vector<std::pair<unsigned int, unsigned int>>>
        faces;
      for (unsigned int c = 0; c < mesh.cells.size(); ++c)
        {
          const auto &v     = mesh.cells[c].vertices;
          const auto &local = v.size() == 4 ? tet_faces : hex_faces;
          for (unsigned int f = 0; f < local.size(); ++f)
            {
              std::array<unsigned int, 4> key;
              key.fill(static_cast<unsigned int>(-1));
              for (unsigned int i = 0; i < local[f].size(); ++i)
                key[i] = v[local[f][i]];
              std::sort(key.begin(), key.end());
              faces[key].emplace_back(c, f);
            }
        }
      return faces;
    }

    /// The boundary faces of @p mesh: each with its cell and its corners (a
    /// triangle's three, or a quadrilateral's four in deal.II's
    /// lexicographic order).
    std::vector<std::pair<unsigned int, std::vector<unsigned int>>>
    boundary_faces(const MeshDescription &mesh)
    {
      std::vector<std::pair<unsigned int, std::vector<unsigned int>>> result;
      for (const auto &[face, cells] : faces_of(mesh))
        if (cells.size() == 1)
          {
            const auto [c, f]           = cells[0];
            const auto               &v = mesh.cells[c].vertices;
            std::vector<unsigned int> corners;
            for (const unsigned int i :
                 (v.size() == 4 ? tet_faces : hex_faces)[f])
              corners.push_back(v[i]);
            result.emplace_back(c, corners);
          }
      return result;
    }

    unsigned int
    root(std::vector<unsigned int> &parent, unsigned int c)
    {
      while (parent[c] != c)
        c = parent[c] = parent[parent[c]];
      return c;
    }
  } // namespace

  std::set<unsigned int>
  boundary_vertices(const MeshDescription &mesh)
  {
    std::set<unsigned int> vertices;
    for (const auto &[c, corners] : boundary_faces(mesh))
      vertices.insert(corners.begin(), corners.end());
    return vertices;
  }

  MeshPieces
  face_connected_pieces(const MeshDescription &mesh)
  {
    const unsigned int        n = mesh.cells.size();
    std::vector<unsigned int> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);

    for (const auto &[face, cells] : faces_of(mesh))
      for (unsigned int i = 1; i < cells.size(); ++i)
        parent[root(parent, cells[i].first)] = root(parent, cells[0].first);

    std::map<unsigned int, unsigned int> size_of_root;
    for (unsigned int c = 0; c < n; ++c)
      ++size_of_root[root(parent, c)];
    std::vector<std::pair<unsigned int, unsigned int>> by_size; // size, root
    for (const auto &[r, size] : size_of_root)
      by_size.emplace_back(size, r);
    std::stable_sort(by_size.begin(),
                     by_size.end(),
                     [](const auto &a, const auto &b) {
                       return a.first > b.first;
                     });

    MeshPieces                           pieces;
    std::map<unsigned int, unsigned int> piece_of_root;
    for (const auto &[size, r] : by_size)
      {
        piece_of_root[r] = pieces.n_cells.size();
        pieces.n_cells.push_back(size);
      }
    pieces.piece_of_cell.resize(n);
    for (unsigned int c = 0; c < n; ++c)
      pieces.piece_of_cell[c] = piece_of_root[root(parent, c)];
    return pieces;
  }

  namespace
  {
    /// True if @p points span at least a plane (three not on one line).
    bool
    span_a_plane(const std::vector<dealii::Point<3>> &points)
    {
      for (unsigned int i = 1; i < points.size(); ++i)
        for (unsigned int j = i + 1; j < points.size(); ++j)
          {
            const auto   a     = points[i] - points[0];
            const auto   b     = points[j] - points[0];
            const double scale = a.norm() * b.norm();
            if (dealii::cross_product_3d(a, b).norm() > 1e-8 * scale &&
                scale > 0)
              return true;
          }
      return false;
    }
  } // namespace

  std::string
  UnheldPiece::text(const double unit_to_mm) const
  {
    std::ostringstream out;
    out << "a piece of " << n_cells << " cell" << (n_cells == 1 ? "" : "s")
        << " (label" << (labels.size() == 1 ? " " : "s ");
    bool first = true;
    for (const Label l : labels)
      {
        out << (first ? "" : ", ") << l;
        first = false;
      }
    out << ") around (" << centre[0] * unit_to_mm << ", "
        << centre[1] * unit_to_mm << ", " << centre[2] * unit_to_mm << ") mm "
        << (n_joints == 0 ? "floats freely" :
            n_joints == 1 ? "pivots about the one vertex joining it to the "
                            "held body" :
                            "hinges about the edge joining it to the held "
                            "body");
    return out.str();
  }

  std::vector<UnheldPiece>
  unheld_pieces(const MeshDescription &mesh,
                const MeshPieces      &pieces,
                const std::set<Label> &held_labels)
  {
    const unsigned int n_pieces = pieces.n_cells.size();
    // The pieces each vertex belongs to.
    std::vector<std::vector<unsigned int>> pieces_of_vertex(
      mesh.vertices.size());
    std::vector<bool> held(n_pieces, false);
    for (unsigned int c = 0; c < mesh.cells.size(); ++c)
      {
        const unsigned int p = pieces.piece_of_cell[c];
        held[p] = held[p] || held_labels.count(mesh.cells[c].material_id);
        for (const unsigned int v : mesh.cells[c].vertices)
          if (std::find(pieces_of_vertex[v].begin(),
                        pieces_of_vertex[v].end(),
                        p) == pieces_of_vertex[v].end())
            pieces_of_vertex[v].push_back(p);
      }
    // Joints with held pieces, until nothing changes.
    std::vector<std::vector<dealii::Point<3>>> joints(n_pieces);
    for (bool changed = true; changed;)
      {
        changed = false;
        for (auto &j : joints)
          j.clear();
        for (unsigned int v = 0; v < pieces_of_vertex.size(); ++v)
          {
            const auto &ps = pieces_of_vertex[v];
            const bool  next_to_held =
              std::any_of(ps.begin(), ps.end(), [&](const unsigned int p) {
                return held[p];
              });
            if (next_to_held)
              for (const unsigned int p : ps)
                if (!held[p])
                  joints[p].push_back(mesh.vertices[v]);
          }
        for (unsigned int p = 0; p < n_pieces; ++p)
          if (!held[p] && span_a_plane(joints[p]))
            held[p] = changed = true;
      }

    std::vector<UnheldPiece>  result(n_pieces);
    std::vector<unsigned int> n_vertices(n_pieces, 0);
    for (unsigned int c = 0; c < mesh.cells.size(); ++c)
      {
        const unsigned int p = pieces.piece_of_cell[c];
        ++result[p].n_cells;
        result[p].labels.insert(mesh.cells[c].material_id);
        for (const unsigned int v : mesh.cells[c].vertices)
          {
            result[p].centre += mesh.vertices[v];
            ++n_vertices[p];
          }
      }
    std::vector<UnheldPiece> unheld;
    for (unsigned int p = 0; p < n_pieces; ++p)
      if (!held[p])
        {
          result[p].centre /= n_vertices[p];
          result[p].n_joints = joints[p].size();
          unheld.push_back(result[p]);
        }
    return unheld;
  }

  RemovedPieces
  remove_small_pieces(MeshDescription &mesh, const double fraction)
  {
    const MeshPieces  pieces = face_connected_pieces(mesh);
    RemovedPieces     removed;
    std::vector<bool> keep(pieces.n_cells.size());
    for (unsigned int p = 0; p < keep.size(); ++p)
      {
        keep[p] = pieces.n_cells[p] >= fraction * pieces.n_cells[0];
        removed.n_pieces += !keep[p];
      }
    if (removed.n_pieces == 0)
      return removed;

    std::vector<unsigned int> kept;
    for (unsigned int c = 0; c < mesh.cells.size(); ++c)
      if (keep[pieces.piece_of_cell[c]])
        kept.push_back(c);
    removed.n_cells = mesh.cells.size() - kept.size();
    mesh            = select_cells(mesh, kept);
    return removed;
  }

  unsigned int
  n_pinched_boundary_edges(const MeshDescription &mesh)
  {
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> n_faces;
    for (const auto &[c, corners] : boundary_faces(mesh))
      {
        // The edges of the face: a triangle's three, or a quadrilateral's
        // four in deal.II's lexicographic order (0-1, 1-3, 3-2, 2-0).
        const std::vector<std::pair<unsigned int, unsigned int>> edges =
          corners.size() == 3 ?
            std::vector<std::pair<unsigned int, unsigned int>>{
              {corners[0], corners[1]},
              {corners[1], corners[2]},
              {corners[2], corners[0]}} :
            std::vector<std::pair<unsigned int, unsigned int>>{
              {corners[0], corners[1]},
              {corners[1], corners[3]},
              {corners[3], corners[2]},
              {corners[2], corners[0]}};
        for (auto [a, b] : edges)
          ++n_faces[{std::min(a, b), std::max(a, b)}];
      }
    unsigned int n_pinched = 0;
    for (const auto &[edge, count] : n_faces)
      n_pinched += count > 2;
    return n_pinched;
  }

  SurfaceGap
  narrowest_surface_gap(const MeshDescription &mesh, const double threshold)
  {
    using dealii::Point;
    using dealii::Tensor;
    using K         = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Triangles = std::vector<K::Triangle_3>;
    using Primitive =
      CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
    using Tree       = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
    const auto point = [&](const unsigned int v) {
      const Point<3> &x = mesh.vertices[v];
      return K::Point_3(x[0], x[1], x[2]);
    };

    // Boundary faces as triangles (a quadrilateral's corners in deal.II's
    // lexicographic order 0 1 2 3 give the triangles 0 1 3 and 0 3 2), with
    // their face's centroid and outward normal.
    Triangles                 triangles;
    std::vector<unsigned int> face_of_triangle;
    std::vector<Point<3>>     centroids;
    std::vector<Tensor<1, 3>> normals;
    for (const auto &[c, corners] : boundary_faces(mesh))
      {
        const auto &v = mesh.cells[c].vertices;
        Point<3>    centroid, cell_centroid;
        for (const unsigned int i : corners)
          centroid += mesh.vertices[i] / double(corners.size());
        for (const unsigned int i : v)
          cell_centroid += mesh.vertices[i] / double(v.size());
        const Tensor<1, 3> a =
          mesh.vertices[corners[1]] - mesh.vertices[corners[0]];
        const Tensor<1, 3> b =
          mesh.vertices[corners.back()] - mesh.vertices[corners[0]];
        Tensor<1, 3> n = cross_product_3d(a, b);
        if (n * (centroid - cell_centroid) < 0)
          n = -n;
        const unsigned int id = centroids.size();
        centroids.push_back(centroid);
        normals.push_back(n / n.norm());
        triangles.emplace_back(point(corners[0]),
                               point(corners[1]),
                               point(corners[corners.size() == 3 ? 2 : 3]));
        face_of_triangle.push_back(id);
        if (corners.size() == 4)
          {
            triangles.emplace_back(point(corners[0]),
                                   point(corners[3]),
                                   point(corners[2]));
            face_of_triangle.push_back(id);
          }
      }

    SurfaceGap gap;
    if (triangles.empty())
      return gap;
    Tree tree(triangles.cbegin(), triangles.cend());
    for (unsigned int id = 0; id < centroids.size(); ++id)
      {
        const Point<3>    &x = centroids[id];
        const Tensor<1, 3> n = normals[id];
        const K::Ray_3     ray(K::Point_3(x[0], x[1], x[2]),
                           K::Vector_3(n[0], n[1], n[2]));
        // The face's own triangles are skipped (the ray starts on them).
        const auto hit =
          tree.first_intersection(ray, [&](const Triangles::const_iterator t) {
            return face_of_triangle[t - triangles.cbegin()] == id;
          });
        if (!hit)
          continue;
        const K::Point_3 *p = boost::get<K::Point_3>(&hit->first);
        if (p == nullptr) // the ray runs inside a face: no gap across
          continue;
        const double width = x.distance(Point<3>(p->x(), p->y(), p->z()));
        gap.n_narrow += width < threshold;
        if (width < gap.width)
          {
            gap.width    = width;
            gap.location = x;
          }
      }
    return gap;
  }

  std::string
  describe_surface_gap(const double width_mm, const dealii::Point<3> &where_mm)
  {
    std::ostringstream line;
    line << "narrowest gap between folds of the surface: " << width_mm
         << " mm, from the face at " << where_mm << " mm";
    return line.str();
  }
} // namespace RestShape
