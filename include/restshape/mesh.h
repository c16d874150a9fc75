// The labelled mesh: reading, checking, tetrahedron-to-hexahedron splitting,
// refinement and writing back to gmsh.
#ifndef restshape_mesh_h
#define restshape_mesh_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <restshape/label_values.h>
#include <restshape/parameters.h>

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace RestShape
{
  /// Vertices (in metres) and cells with labels, before a Triangulation.
  struct MeshDescription
  {
    std::vector<dealii::Point<3>>    vertices;
    std::vector<dealii::CellData<3>> cells;
  };

  /**
   * Read a gmsh file into a description in metres. Throws InputError naming
   * the file and "Mesh/File" for missing, unreadable or malformed files and
   * for meshes that are not purely tetrahedral or purely hexahedral.
   */
  MeshDescription
  read_gmsh(const std::string &file, const double length_unit);

  /**
   * Check coordinates and cell orientation: every vertex finite, every cell
   * with a positive Jacobian determinant at its corners (deal.II's vertex
   * order). Throws InputError naming @p file for NaN coordinates and for
   * inverted or zero-volume cells.
   */
  void
  check_mesh(const MeshDescription &mesh, const std::string &file);

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

  /**
   * Write the active cells of @p tria as gmsh 2.2 ASCII with labels as
   * physical volume tags. Vertex v is written at position(v) divided by
   * @p length_unit. Written atomically.
   */
  void
  write_gmsh(const dealii::Triangulation<3>                      &tria,
             const std::function<dealii::Point<3>(unsigned int)> &position,
             const double                                         length_unit,
             const std::string                                   &file);

  /// The same for a mesh description (vertices in metres).
  void
  write_gmsh(const MeshDescription &mesh,
             const double           length_unit,
             const std::string     &file);

  /**
   * The computational mesh of a scene: the triangulation (distributed when
   * run under MPI: shared for tetrahedra, p4est for hexahedra) and its
   * labels.
   */
  class LabelledMesh
  {
  public:
    LabelledMesh(const MeshParameters &parameters, const MPI_Comm comm);

    dealii::Triangulation<3> &
    triangulation();
    const dealii::Triangulation<3> &
    triangulation() const;

    bool
    is_simplex() const;

    /// Labels present in the mesh, with their cell counts (coarse mesh).
    const std::map<Label, unsigned int> &
    label_counts() const;

    std::set<Label>
    labels() const;

    /// Diagonal of the bounding box (m).
    double
    diameter() const;

    /**
     * Narrowest gap between folds of the surface of the mesh as read (m,
     * infinity if none) and where it starts (narrowest_surface_gap() in
     * mesh_pieces.h; computed on rank 0 only, infinity elsewhere). Thin
     * flaps of tissue border such gaps; refined solutions there converge
     * slowly and may have several equilibria.
     */
    std::pair<double, dealii::Point<3>>
    narrowest_gap() const;

    /// Smallest cell diameter of the active mesh (m).
    double
    minimum_cell_diameter() const;

    /**
     * The vertex positions (m) of a rest-shape file: a gmsh file with the
     * cells of the active mesh, in the same order and with the same vertex
     * order (what write_gmsh() writes, e.g. an inverse run's
     * rest_shape.msh, with the same Mesh settings). Indexed by vertex of
     * the triangulation. Throws InputError naming Mesh/Rest shape file if
     * the file does not match, or has inverted cells.
     */
    std::vector<dealii::Point<3>>
    read_rest_shape(const std::string &file) const;

    /**
     * Refine every cell once: tetrahedra by red refinement of the mesh
     * description (the triangulation is rebuilt: DoFHandlers must be
     * re-initialised; children of cell i are cells 8i..8i+7), hexahedra by
     * deal.II. @p before_change, if given, is called once the cells are
     * marked and before the mesh changes (to prepare a StateTransfer).
     */
    void
    refine_global(const std::function<void()> &before_change = {});

    /**
     * Hexahedra only: refine the @p refine_fraction of the cells with the
     * largest @p indicators (one per active cell) and coarsen the
     * @p coarsen_fraction with the smallest; hanging nodes are constrained
     * by the forward problem. @p before_change as for refine_global().
     */
    void
    refine_adaptive(const dealii::Vector<float> &indicators,
                    const double                 refine_fraction,
                    const double                 coarsen_fraction,
                    const std::function<void()> &before_change = {});

    const MeshParameters parameters;

  private:
    void
    create_triangulation();
    /// Hexahedra: smooth the marks, call @p before_change, refine.
    void
    execute_refinement(const std::function<void()> &before_change);

    MeshDescription                           description; // tetrahedra only
    std::unique_ptr<dealii::Triangulation<3>> tria;
    std::map<Label, unsigned int>             counts;
    double                                    bounding_diameter;
    std::pair<double, dealii::Point<3>>       gap;
  };
} // namespace RestShape

#endif
