// Transforms of a mesh description.
#include <deal.II/base/utilities.h>

#include <restshape/mesh/mesh_transforms.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <numeric>

namespace RestShape
{
  using namespace dealii;

  Point<3>
  centroid(const std::vector<Point<3>>     &v,
           const std::vector<unsigned int> &indices)
  {
    Point<3> c;
    for (const unsigned int i : indices)
      c += v[i];
    return c / static_cast<double>(indices.size());
  }

  MeshDescription
  select_cells(const MeshDescription           &mesh,
               const std::vector<unsigned int> &cells)
  {
    MeshDescription result;
    result.cells.reserve(cells.size());
    result.rest_nodes                = mesh.rest_nodes; // by position
    const unsigned int        unused = numbers::invalid_unsigned_int;
    std::vector<unsigned int> new_index(mesh.vertices.size(), unused);
    for (const unsigned int c : cells)
      {
        CellData<3> cell = mesh.cells[c];
        for (unsigned int &v : cell.vertices)
          {
            if (new_index[v] == unused)
              {
                new_index[v] = result.vertices.size();
                result.vertices.push_back(mesh.vertices[v]);
                if (!mesh.targets.empty())
                  result.targets.push_back(mesh.targets[v]);
              }
            v = new_index[v];
          }
        result.add_part(cell, mesh, c);
      }
    return result;
  }

  namespace
  {
    /// The midpoint vertex of every edge, created once.
    class EdgeMidpoints
    {
    public:
      EdgeMidpoints(MeshDescription &mesh)
        : mesh(mesh)
      {}

      unsigned int
      operator()(const unsigned int a, const unsigned int b)
      {
        const std::array<unsigned int, 2> key{{std::min(a, b), std::max(a, b)}};
        const auto                        it = index.find(key);
        if (it != index.end())
          return it->second;
        return index[key] = mesh.add_centroid({a, b});
      }

    private:
      MeshDescription                                    &mesh;
      std::map<std::array<unsigned int, 2>, unsigned int> index;
    };

    /// A tetrahedron with positive orientation (two vertices swapped if
    /// needed).
    CellData<3>
    oriented_tet(const std::vector<Point<3>> &v,
                 std::array<unsigned int, 4>  t,
                 const types::material_id     label)
    {
      if (triple_product(v[t[1]] - v[t[0]],
                         v[t[2]] - v[t[0]],
                         v[t[3]] - v[t[0]]) < 0)
        std::swap(t[1], t[2]);
      CellData<3> cell(4);
      cell.vertices.assign(t.begin(), t.end());
      cell.material_id = label;
      return cell;
    }
  } // namespace

  MeshDescription
  refine_tetrahedra(const MeshDescription &tets)
  {
    MeshDescription fine;
    fine.vertices = tets.vertices;
    fine.targets  = tets.targets;
    EdgeMidpoints midpoint(fine);
    for (unsigned int c = 0; c < tets.cells.size(); ++c)
      {
        const auto &tet = tets.cells[c];
        const auto &t   = tet.vertices;
        // m[i][j]: midpoint of edge (i, j).
        unsigned int m[4][4];
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = i + 1; j < 4; ++j)
            m[i][j] = m[j][i] = midpoint(t[i], t[j]);
        const auto &v = fine.vertices;
        for (unsigned int i = 0; i < 4; ++i)
          {
            std::array<unsigned int, 4> corner;
            for (unsigned int j = 0; j < 4; ++j)
              corner[j] = (i == j) ? t[i] : m[i][j];
            fine.add_part(oriented_tet(v, corner, tet.material_id), tets, c);
          }
        // The octahedron: diagonals join midpoints of opposite edges
        // (x y)-(z w); the equator around (x y)-(z w) is xz, xw, yw, yz.
        static const unsigned int diagonals[3][4] = {{0, 1, 2, 3},
                                                     {0, 2, 1, 3},
                                                     {0, 3, 1, 2}};
        unsigned int              best            = 0;
        double                    shortest = std::numeric_limits<double>::max();
        for (unsigned int k = 0; k < 3; ++k)
          {
            const auto  &d      = diagonals[k];
            const double length = v[m[d[0]][d[1]]].distance(v[m[d[2]][d[3]]]);
            if (length < shortest)
              {
                shortest = length;
                best     = k;
              }
          }
        const auto        &d = diagonals[best];
        const unsigned int x = d[0], y = d[1], z = d[2], w = d[3];
        const unsigned int equator[4] = {m[x][z], m[x][w], m[y][w], m[y][z]};
        for (unsigned int e = 0; e < 4; ++e)
          fine.add_part(
            oriented_tet(v,
                         {{m[x][y], m[z][w], equator[e], equator[(e + 1) % 4]}},
                         tet.material_id),
            tets,
            c);
      }
    return fine;
  }

  MeshDescription
  split_tetrahedra_into_hexahedra(const MeshDescription &tets)
  {
    // Vertices get a rank: 0 tet vertex, 1 edge midpoint, 2 face centroid,
    // 3 cell centroid. Every hexahedron is numbered so that each of its
    // edges runs from lower to higher rank, which orients all edges of the
    // mesh consistently (no reordering needed).
    MeshDescription                                     hexes;
    std::map<std::array<unsigned int, 2>, unsigned int> edge_vertex;
    std::map<std::array<unsigned int, 3>, unsigned int> face_vertex;
    hexes.vertices = tets.vertices;
    hexes.targets  = tets.targets;

    const auto new_vertex = [&](const std::vector<unsigned int> &of) {
      return hexes.add_centroid(of);
    };
    const auto edge = [&](unsigned int a, unsigned int b) {
      std::array<unsigned int, 2> key{{std::min(a, b), std::max(a, b)}};
      const auto                  it = edge_vertex.find(key);
      if (it != edge_vertex.end())
        return it->second;
      return edge_vertex[key] = new_vertex({a, b});
    };
    const auto face = [&](unsigned int a, unsigned int b, unsigned int c) {
      std::array<unsigned int, 3> key{{a, b, c}};
      std::sort(key.begin(), key.end());
      const auto it = face_vertex.find(key);
      if (it != face_vertex.end())
        return it->second;
      return face_vertex[key] = new_vertex({a, b, c});
    };

    for (unsigned int c = 0; c < tets.cells.size(); ++c)
      {
        const auto        &tet    = tets.cells[c];
        const auto        &t      = tet.vertices;
        const unsigned int center = new_vertex(t);
        for (unsigned int i = 0; i < 4; ++i)
          {
            std::array<unsigned int, 3> o;
            for (unsigned int k = 0, n = 0; k < 4; ++k)
              if (k != i)
                o[n++] = t[k];
            const Point<3> &p = tets.vertices[t[i]];
            if (triple_product(tets.vertices[o[0]] - p,
                               tets.vertices[o[1]] - p,
                               tets.vertices[o[2]] - p) < 0)
              std::swap(o[1], o[2]);

            CellData<3> hex(8);
            hex.vertices    = {t[i],
                               edge(t[i], o[0]),
                               edge(t[i], o[1]),
                               face(t[i], o[0], o[1]),
                               edge(t[i], o[2]),
                               face(t[i], o[0], o[2]),
                               face(t[i], o[1], o[2]),
                               center};
            hex.material_id = tet.material_id;
            hexes.add_part(hex, tets, c);
          }
      }
    return hexes;
  }

  void
  sort_along_hilbert_curve(MeshDescription &mesh)
  {
    std::vector<Point<3>> centroids;
    centroids.reserve(mesh.cells.size());
    for (const auto &cell : mesh.cells)
      centroids.push_back(centroid(mesh.vertices, cell.vertices));
    // 21 bits per coordinate: positions resolved to 1/2e6 of the bounding
    // box (about 0.1 micrometre for a brain).
    const auto curve =
      Utilities::inverse_Hilbert_space_filling_curve(centroids, 21);
    std::vector<std::uint64_t> key(curve.size());
    for (unsigned int c = 0; c < curve.size(); ++c)
      key[c] = Utilities::pack_integers<3>(curve[c], 21);
    std::vector<unsigned int> order(mesh.cells.size());
    std::iota(order.begin(), order.end(), 0u);
    // Grouped by label first: gmsh reads the cells of a file grouped by
    // entity (the label, in write_gmsh), and a rest_shape.msh must come
    // back in the order it was written.
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       const auto la = mesh.cells[a].material_id;
                       const auto lb = mesh.cells[b].material_id;
                       return la < lb || (la == lb && key[a] < key[b]);
                     });

    mesh = select_cells(mesh, order);
  }
} // namespace RestShape
