// Cell order of the meshes (sort_along_hilbert_curve, source/mesh.cc), on
// the committed coarse brain (meshes/brain_coarse.msh, in CGAL's order):
//  1. The sorted mesh has the same cells: the same multiset of (label,
//     vertex positions in cell order), every vertex used.
//  2. Locality: consecutive cells' centroids are far closer than in the
//     file's order (measured in mean edge lengths), and the vertices of a
//     cell are close in number (the median spread of indices within a
//     cell, relative to the number of vertices).
//  3. Sorting a sorted mesh changes nothing, and the cells are grouped by
//     label in increasing order (the order in which gmsh reads a written
//     mesh back: rest_shape.msh depends on it).
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>

#include <algorithm>
#include <tuple>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  using CellKey = std::tuple<unsigned int, std::vector<double>>;

  std::vector<CellKey>
  cell_keys(const MeshDescription &mesh)
  {
    std::vector<CellKey> keys;
    for (const auto &cell : mesh.cells)
      {
        std::vector<double> x;
        for (const unsigned int v : cell.vertices)
          for (unsigned int d = 0; d < 3; ++d)
            x.push_back(mesh.vertices[v][d]);
        keys.emplace_back(cell.material_id, x);
      }
    std::sort(keys.begin(), keys.end());
    return keys;
  }

  /// Mean distance between consecutive cells' centroids / mean edge length.
  double
  consecutive_distance(const MeshDescription &mesh)
  {
    double distance = 0, edge = 0;
    for (unsigned int c = 0; c < mesh.cells.size(); ++c)
      {
        const auto &v = mesh.cells[c].vertices;
        edge += mesh.vertices[v[0]].distance(mesh.vertices[v[1]]);
        if (c > 0)
          distance +=
            centroid(mesh.vertices, mesh.cells[c].vertices)
              .distance(centroid(mesh.vertices, mesh.cells[c - 1].vertices));
      }
    return (distance / (mesh.cells.size() - 1)) / (edge / mesh.cells.size());
  }

  /// Median over the cells of (largest - smallest vertex index of the
  /// cell) / number of vertices. (The mean is dominated by the cells where
  /// the curve folds back.)
  double
  index_spread(const MeshDescription &mesh)
  {
    std::vector<double> spread;
    for (const auto &cell : mesh.cells)
      {
        const auto [low, high] =
          std::minmax_element(cell.vertices.begin(), cell.vertices.end());
        spread.push_back(*high - *low);
      }
    std::nth_element(spread.begin(),
                     spread.begin() + spread.size() / 2,
                     spread.end());
    return spread[spread.size() / 2] / mesh.vertices.size();
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MeshDescription file   = read_gmsh("meshes/brain_coarse.msh", 1e-3);
  MeshDescription       sorted = file;
  sort_along_hilbert_curve(sorted);

  check_between("cells",
                sorted.cells.size(),
                file.cells.size(),
                file.cells.size());
  std::vector<unsigned int> uses(sorted.vertices.size(), 0);
  for (const auto &cell : sorted.cells)
    for (const unsigned int v : cell.vertices)
      ++uses[v];
  check_between("unused vertices of the sorted mesh",
                std::count(uses.begin(), uses.end(), 0u),
                0,
                0);
  check_between("vertices",
                sorted.vertices.size(),
                file.vertices.size(),
                file.vertices.size());
  check_between("the same cells (labels, vertex positions in cell order)",
                cell_keys(sorted) == cell_keys(file),
                1,
                1);

  const double file_distance   = consecutive_distance(file);
  const double sorted_distance = consecutive_distance(sorted);
  std::cout << "consecutive centroid distance (edge lengths): file "
            << file_distance << ", sorted " << sorted_distance << std::endl;
  check_below("sorted / file consecutive distance",
              sorted_distance / file_distance,
              0.5);
  check_below("sorted consecutive distance (edge lengths)", sorted_distance, 2);
  std::cout << "vertex index spread in a cell / vertices: file "
            << index_spread(file) << ", sorted " << index_spread(sorted)
            << std::endl;
  check_below("sorted / file index spread",
              index_spread(sorted) / index_spread(file),
              0.25);

  MeshDescription again = sorted;
  sort_along_hilbert_curve(again);
  bool same = again.vertices == sorted.vertices;
  for (unsigned int c = 0; same && c < sorted.cells.size(); ++c)
    same = again.cells[c].vertices == sorted.cells[c].vertices &&
           again.cells[c].material_id == sorted.cells[c].material_id;
  check_between("sorting a sorted mesh changes nothing", same, 1, 1);
  bool grouped = true;
  for (unsigned int c = 1; c < sorted.cells.size(); ++c)
    grouped =
      grouped && sorted.cells[c - 1].material_id <= sorted.cells[c].material_id;
  check_between("cells grouped by label in increasing order", grouped, 1, 1);
  return exit_code();
}
