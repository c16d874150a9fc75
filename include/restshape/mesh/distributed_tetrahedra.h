// A tetrahedral mesh split among MPI ranks without any rank holding the
// whole triangulation (parallel::fullydistributed).
#ifndef restshape_mesh_distributed_tetrahedra_h
#define restshape_mesh_distributed_tetrahedra_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria_description.h>

#include <restshape/mesh/mesh_description.h>

#include <cstddef>
#include <vector>

namespace RestShape
{
  /**
   * Which rank owns which cells: rank r owns the cells starts[r] to
   * starts[r + 1] - 1 of a mesh in its order (contiguous pieces of the
   * Hilbert-curve order that sort_along_hilbert_curve() gives, within each
   * label).
   */
  class CellPartition
  {
  public:
    CellPartition() = default;
    /// @p n_cells cells in @p n_ranks pieces of (almost) equal size.
    CellPartition(const std::size_t n_cells, const unsigned int n_ranks);

    /// The rank that owns cell @p cell.
    unsigned int
    owner(const std::size_t cell) const;

    /// The same cells refined once (cell i into cells 8i to 8i + 7): the
    /// children stay with the rank of their parent.
    CellPartition
    refined() const;

  private:
    std::vector<std::size_t> starts;
  };

  /// What one rank holds of a mesh: the description of its cells and of
  /// the cells that share a vertex with them (its ghosts), and the index in
  /// the mesh of each of its vertices.
  struct LocalPart
  {
    dealii::TriangulationDescription::Description<3, 3> description;
    std::vector<unsigned int>                           global_vertices;
    /// The mesh's targets and mass ratios (if any) of the part's vertices
    /// and cells, in the order of the part.
    std::vector<dealii::Point<3>> targets;
    std::vector<double>           mass_ratios;
  };

  /**
   * The part of @p mesh (tetrahedra) that this rank of @p comm holds under
   * @p partition, for parallel::fullydistributed::Triangulation. The
   * coarse cell id of a cell is its index in @p mesh; the local vertices
   * keep the order of their indices in @p mesh (so that every rank orients
   * shared edges and faces alike).
   */
  LocalPart
  local_part(const MeshDescription &mesh,
             const CellPartition   &partition,
             const MPI_Comm         comm);

  /// The parts of a mesh that gather_mesh() collects from each rank.
  struct RankPart
  {
    const dealii::Triangulation<3> &tria;
    /// Index in the whole mesh of each vertex of @p tria, and their count.
    const std::vector<unsigned int> &global_vertices;
    std::size_t                      n_vertices;
    /// By vertex of @p tria: positions, targets (or empty).
    const std::vector<dealii::Point<3>> &positions;
    const std::vector<dealii::Point<3>> &targets;
    /// By coarse cell index of @p tria (or empty).
    const std::vector<double> &mass_ratios;
  };

  /**
   * The whole mesh from the owned cells of every rank's @p part (cells in
   * the order of their coarse cell ids, vertices numbered as in the whole
   * mesh, at the given positions; with targets and mass ratios if the
   * parts have them). On rank @p root only (empty elsewhere), or on every
   * rank for root = numbers::invalid_unsigned_int.
   */
  MeshDescription
  gather_mesh(const RankPart &part, const unsigned int root);
} // namespace RestShape

#endif
