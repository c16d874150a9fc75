#include <restshape/mesh_pieces.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

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

    unsigned int
    root(std::vector<unsigned int> &parent, unsigned int c)
    {
      while (parent[c] != c)
        c = parent[c] = parent[parent[c]];
      return c;
    }
  } // namespace

  MeshPieces
  face_connected_pieces(const MeshDescription &mesh)
  {
    const unsigned int        n = mesh.cells.size();
    std::vector<unsigned int> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);

    // Every face, as its sorted vertex numbers (unused entries the largest
    // number), to the first cell that has it.
    std::map<std::array<unsigned int, 4>, unsigned int> first_cell;
    for (unsigned int c = 0; c < n; ++c)
      {
        const auto &v = mesh.cells[c].vertices;
        for (const auto &face : v.size() == 4 ? tet_faces : hex_faces)
          {
            std::array<unsigned int, 4> key;
            key.fill(static_cast<unsigned int>(-1));
            for (unsigned int i = 0; i < face.size(); ++i)
              key[i] = v[face[i]];
            std::sort(key.begin(), key.end());
            const auto [it, inserted] = first_cell.emplace(key, c);
            if (!inserted)
              parent[root(parent, c)] = root(parent, it->second);
          }
      }

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

    MeshDescription           kept;
    std::vector<unsigned int> new_index(mesh.vertices.size(),
                                        static_cast<unsigned int>(-1));
    for (unsigned int c = 0; c < mesh.cells.size(); ++c)
      {
        if (!keep[pieces.piece_of_cell[c]])
          {
            ++removed.n_cells;
            continue;
          }
        dealii::CellData<3> cell = mesh.cells[c];
        for (auto &v : cell.vertices)
          {
            if (new_index[v] == static_cast<unsigned int>(-1))
              {
                new_index[v] = kept.vertices.size();
                kept.vertices.push_back(mesh.vertices[v]);
              }
            v = new_index[v];
          }
        kept.cells.push_back(cell);
      }
    mesh = std::move(kept);
    return removed;
  }
} // namespace RestShape
