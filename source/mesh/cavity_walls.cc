#include <deal.II/base/mpi.h>

#include <restshape/mesh/cavity_walls.h>

#include <algorithm>
#include <map>
#include <numeric>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    using FaceKey = std::vector<double>;

    /// The face's vertices, sorted, as one list of coordinates.
    FaceKey
    face_key(const CellAccessor<3, 3> &cell, const unsigned int f)
    {
      const auto            face = cell.face(f);
      std::vector<Point<3>> v;
      for (const unsigned int i : face->vertex_indices())
        v.push_back(face->vertex(i));
      std::sort(v.begin(), v.end(), [](const Point<3> &a, const Point<3> &b) {
        return std::lexicographical_compare(a.begin_raw(),
                                            a.end_raw(),
                                            b.begin_raw(),
                                            b.end_raw());
      });
      FaceKey key;
      for (const Point<3> &p : v)
        key.insert(key.end(), p.begin_raw(), p.end_raw());
      return key;
    }

    /// The face's part of the volume its surface encloses, 1/3 x . n dA
    /// with n pointing out of @p cell (m^3).
    double
    enclosed_volume(const CellAccessor<3, 3> &cell, const unsigned int f)
    {
      const auto         face = cell.face(f);
      const unsigned int n    = face->n_vertices();
      // Area vector of the (planar or bilinear) face: half the sum of the
      // cross products of consecutive vertices around its centre.
      const Point<3> c = face->center();
      // deal.II's vertex order of a quadrilateral is lexicographic: turn
      // it into the cycle 0, 1, 3, 2.
      std::vector<unsigned int> cycle(n);
      std::iota(cycle.begin(), cycle.end(), 0);
      if (n == 4)
        cycle = {0, 1, 3, 2};
      Tensor<1, 3> area;
      for (unsigned int i = 0; i < n; ++i)
        area += 0.5 * cross_product_3d(face->vertex(cycle[i]) - c,
                                       face->vertex(cycle[(i + 1) % n]) - c);
      if (area * (c - cell.center()) < 0)
        area = -area;
      return c * area / 3.;
    }

    /// Union-find's root of @p i.
    unsigned int
    root(std::vector<unsigned int> &parent, unsigned int i)
    {
      while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    }
  } // namespace

  CavityWalls::CavityWalls(const LabelledMesh &mesh)
  {
    // Every rank's surface faces of its owned cells, to every rank.
    std::vector<std::pair<FaceKey, double>> mine;
    for (const auto &cell : mesh.triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (mesh.at_surface(*cell, f))
            mine.emplace_back(face_key(*cell, f), enclosed_volume(*cell, f));
    std::vector<std::pair<FaceKey, double>> faces;
    for (const auto &part :
         Utilities::MPI::all_gather(mesh.triangulation().get_communicator(),
                                    mine))
      faces.insert(faces.end(), part.begin(), part.end());

    // Faces that share a vertex belong to the same part.
    std::vector<unsigned int> parent(faces.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::map<std::array<double, 3>, unsigned int> vertex_face;
    for (unsigned int i = 0; i < faces.size(); ++i)
      for (unsigned int k = 0; k + 2 < faces[i].first.size(); k += 3)
        {
          const std::array<double, 3> x = {
            {faces[i].first[k], faces[i].first[k + 1], faces[i].first[k + 2]}};
          const auto [it, inserted] = vertex_face.emplace(x, i);
          if (!inserted)
            parent[root(parent, i)] = root(parent, it->second);
        }
    std::map<unsigned int, double> volume; // by part
    for (unsigned int i = 0; i < faces.size(); ++i)
      volume[root(parent, i)] += faces[i].second;
    for (const auto &[part, v] : volume)
      if (v < 0)
        {
          ++cavities;
          volumes.push_back(-v);
        }
      else
        ++outer;
    for (unsigned int i = 0; i < faces.size(); ++i)
      if (volume[root(parent, i)] < 0)
        walls.insert(faces[i].first);
  }

  bool
  CavityWalls::contains(const CellAccessor<3, 3> &cell,
                        const unsigned int        f) const
  {
    return !walls.empty() && walls.count(face_key(cell, f)) > 0;
  }
} // namespace RestShape
