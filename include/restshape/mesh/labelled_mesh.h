// The computational mesh of a scene: the (distributed) triangulation, its
// labels and its refinement.
#ifndef restshape_mesh_labelled_mesh_h
#define restshape_mesh_labelled_mesh_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <restshape/base/label_values.h>
#include <restshape/mesh/distributed_tetrahedra.h>
#include <restshape/mesh/mesh_description.h>
#include <restshape/mesh/mesh_parameters.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace RestShape
{
  struct MeshPieces;
  struct UnheldPiece;

  /**
   * The computational mesh of a scene: the triangulation (distributed when
   * run under MPI: fully distributed for tetrahedra, each rank holding its
   * cells and their neighbours; p4est for hexahedra) and its labels.
   */
  class LabelledMesh
  {
  public:
    /// Called with the number of cells of the mesh file (after a split
    /// into hexahedra) before it is refined: may throw to refuse the run.
    using SizeCheck = std::function<void(std::size_t cells)>;

    LabelledMesh(const MeshParameters &parameters,
                 const MPI_Comm        comm,
                 const SizeCheck      &check_size = {});

    dealii::Triangulation<3> &
    triangulation();
    const dealii::Triangulation<3> &
    triangulation() const;

    bool
    is_simplex() const;

    /// Metres per unit of the mesh file (Mesh/Length unit).
    double
    length_unit() const
    {
      return parameters.length_unit;
    }

    /// Labels present in the mesh, with their cell counts (coarse mesh).
    const std::map<Label, unsigned int> &
    label_counts() const;

    std::set<Label>
    labels() const;

    /// The names of labels (scene_label_names()).
    const LabelNames &
    label_names() const;

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

    /**
     * The mass of @p cell over its density times its volume: 1, or for a
     * rest shape written by an inverse run (rest_shape.msh), the ratio
     * that gives it its mass in the image.
     */
    double
    mass_ratio(const dealii::CellAccessor<3, 3> &cell) const;

    /**
     * The index of @p cell among the active cells of the whole mesh, the
     * same on any number of ranks (tetrahedra; hexahedra: its active cell
     * index, the whole mesh's on one rank).
     */
    std::size_t
    cell_index(const dealii::CellAccessor<3, 3> &cell) const;

    /**
     * Whether face @p f of @p cell (owned or ghost) lies on the surface of
     * the mesh. On tetrahedra on several ranks, faces of ghost cells that
     * only this rank's part ends at are not, nor are surface faces of
     * ghost cells away from the owned cells (no owned DoF lies on them).
     */
    bool
    at_surface(const dealii::CellAccessor<3, 3> &cell,
               const unsigned int                f) const;

    /**
     * Write the active cells of the whole mesh (from every rank) as gmsh
     * (write_gmsh()) on rank 0: vertex v of the triangulation at
     * @p positions[v] (m), with the rest-shape data, targets (targets(),
     * else the mesh's vertices) and @p rest_mass_ratios (by cell_index()).
     * Not for hexahedra on several ranks (no rank knows the whole mesh).
     */
    /// What write_gmsh() adds to a rest shape on one rank (not on a
    /// partitioned mesh): each vertex's equilibrium (by vertex of the
    /// triangulation, m; empty: none) and, for quadratic tetrahedra, each
    /// active cell's six edge nodes' rest and equilibrium positions (m, in
    /// the order of gmsh_tet10_edges; empty: linear cells).
    struct RestNodes
    {
      std::vector<dealii::Point<3>>                equilibria;
      std::vector<std::array<dealii::Point<3>, 6>> edge_rest, edge_equilibria;
    };
    void
    write_gmsh(const std::vector<dealii::Point<3>> &positions,
               const std::string                   &file,
               const std::vector<double>           &rest_mass_ratios,
               const RestNodes                     &nodes = RestNodes()) const;
    /// A rest_shape.msh's edge nodes and equilibria (rest_shape_nodes.h),
    /// as read; empty for other meshes.
    const RestShapeNodes &
    rest_shape_nodes() const
    {
      return rest_nodes;
    }

    /**
     * The target position (m) of every vertex of the mesh as read (and, on
     * tetrahedra, of every vertex of its refinements), indexed by vertex of
     * the triangulation: given by a rest_shape.msh; empty for other meshes.
     */
    const std::vector<dealii::Point<3>> &
    targets() const;

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
     * Refine every cell once: tetrahedra by red refinement of the coarse
     * cells (the triangulation is rebuilt: DoFHandlers must be
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

    /// The face-connected pieces of the mesh as read that no cell of
    /// @p held_labels holds (mesh_pieces.h); none if it is one piece.
    std::vector<UnheldPiece>
    unheld_pieces(const std::set<Label> &held_labels) const;

    const MeshParameters parameters;

  private:
    /// The mesh as read and its pieces, kept if it has several.
    std::shared_ptr<const MeshDescription> pieces_mesh;
    std::shared_ptr<const MeshPieces>      pieces;

    /// The triangulation of @p mesh (its cells are not kept: tetrahedra
    /// are described again from the triangulation when refined).
    void
    create_triangulation(MeshDescription &&mesh);
    /// Tetrahedra: the coarse cells, vertices, targets and mass ratios.
    MeshDescription
    coarse_description() const;
    /// Hexahedra: smooth the marks, call @p before_change, refine.
    void
    execute_refinement(const std::function<void()> &before_change);

    std::unique_ptr<dealii::Triangulation<3>> tria;
    /// Tetrahedra on several ranks: who owns which cell, the index in the
    /// whole mesh of each vertex of the triangulation, and their number.
    std::unique_ptr<CellPartition>      partition;
    std::vector<unsigned int>           global_vertices;
    std::size_t                         n_whole_vertices = 0;
    std::vector<bool>                   of_owned_cell; // by vertex
    std::map<Label, unsigned int>       counts;
    double                              bounding_diameter;
    std::pair<double, dealii::Point<3>> gap;
    std::vector<double> mass_ratios; // by coarse cell of the triangulation
    std::vector<dealii::Point<3>> vertex_targets;
    RestShapeNodes                rest_nodes; // rest_shape_nodes()
    LabelNames                    names;
  };

  /**
   * The names of the labels of a scene: the $PhysicalNames of Mesh/File
   * and the table of Mesh/Label names (throws InputError naming it if it
   * cannot be read or names a label differently).
   */
  LabelNames
  scene_label_names(const MeshParameters &parameters);
} // namespace RestShape

#endif
