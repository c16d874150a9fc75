// Transforms of a mesh description: red refinement of tetrahedra, the
// tetrahedron-to-hexahedron split, cell selection and the Hilbert sort.
#ifndef restshape_mesh_mesh_transforms_h
#define restshape_mesh_mesh_transforms_h

#include <restshape/mesh/mesh_description.h>

#include <vector>

namespace RestShape
{
  /**
   * Red refinement of every tetrahedron into eight (Bey 1995): four corner
   * tetrahedra and the inner octahedron split along its shortest diagonal,
   * which keeps the shape quality bounded over many levels (deal.II 9.4's
   * own refinement of tetrahedra uses a fixed diagonal and degrades it).
   */
  MeshDescription
  refine_tetrahedra(const MeshDescription &tets);

  /// The centroid of the vertices @p indices of @p vertices.
  dealii::Point<3>
  centroid(const std::vector<dealii::Point<3>> &vertices,
           const std::vector<unsigned int>     &indices);

  /**
   * The cells @p cells of @p mesh, in that order, with the vertices they
   * use, renumbered in the order of first use (vertices no cell uses are
   * dropped).
   */
  MeshDescription
  select_cells(const MeshDescription           &mesh,
               const std::vector<unsigned int> &cells);

  /**
   * Reorder a mesh for memory locality: cells grouped by label (in
   * increasing order, as gmsh reads them back) and, within a label, along a
   * Hilbert curve through their centroids; vertices in the order the cells
   * first use them. The same cells, labels and vertex order within each
   * cell. Mesh generators (CGAL's among them) write cells in an order close
   * to random, and deal.II numbers the degrees of freedom in cell order, so
   * every cell's entries would be scattered over the vectors and the matrix.
   */
  void
  sort_along_hilbert_curve(MeshDescription &mesh);

  /// Split every tetrahedron into four hexahedra (labels kept).
  MeshDescription
  split_tetrahedra_into_hexahedra(const MeshDescription &tets);

} // namespace RestShape

#endif
