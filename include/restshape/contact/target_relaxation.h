// The admissible target where projecting onto the obstacle inverts cells:
// the nodes of those cells follow their neighbours until none is inverted.
#ifndef restshape_target_relaxation_h
#define restshape_target_relaxation_h

#include <restshape/contact/obstacle.h>
#include <restshape/fem/discretization.h>

#include <string>
#include <vector>

namespace RestShape
{
  /// What relax() did (all counts summed over the ranks).
  struct TargetRelaxationResult
  {
    unsigned int inverted_before = 0; // cells inverted by the projection
    unsigned int inverted_after  = 0; // cells still inverted (0: success)
    unsigned int below_threshold = 0; // cells below minimum_jacobian at end
    unsigned int sweeps          = 0;
    unsigned int moved_nodes     = 0; // nodes whose shift changed
    double       largest_change  = 0; // m
    std::string  where;               // a cell still inverted, if any
  };

  /**
   * Relaxation of the admissible target's shift s (target - image, m).
   * Projecting every node beyond the obstacle onto it can invert cells:
   * a P2 cell whose mid-edge nodes move farther than its vertices (a
   * curved obstacle, a flat boundary cell), or an obstacle that cuts
   * deeper into the image than its boundary cells are thick. No rest
   * shape reaches an inverted target. The nodes of such cells join a set
   * that is smoothed, one Jacobi sweep at a time: a node that is not a
   * vertex takes the linear (P1/Q1) interpolation of its cell's vertex
   * shifts, which makes the cell's map what a P1/Q1 cell would do; a
   * vertex, once that does not suffice (every other node of a cell still
   * inverted is in the set), the mean shift of the vertices it shares a
   * cell with. A smoothed node that ends beyond the obstacle is projected
   * onto it again. The set grows with the nodes of every cell still below
   * the Jacobian threshold, until no cell is, or none is inverted and
   * sweeping no longer changes that (or the sweep limit is reached);
   * fixed DoFs never move. Nodes outside the set keep their
   * image position or projection: the change is local.
   */
  class TargetRelaxation
  {
  public:
    TargetRelaxation(const Discretization &discretization,
                     const Obstacle       &obstacle);

    /// Relax @p shift (owned, m) in place.
    TargetRelaxationResult
    relax(VectorType &shift) const;

    /// Smallest det(I + grad s) at a quadrature point that the relaxed
    /// target keeps in every cell.
    static constexpr double minimum_jacobian = 0.2;
    /// Limit on the Jacobi sweeps.
    static constexpr unsigned int max_sweeps = 500;
    /// A node whose shift changed by less (m) is not counted as moved
    /// (round-off of sums in another order on another number of ranks).
    static constexpr double negligible_change = 1e-12;
    /// Sweeps without change after which a state without inverted cells
    /// is kept although some cells stay below minimum_jacobian.
    static constexpr unsigned int patience = 20;

  private:
    /// The nodes (indices into forward.discretization().relevant_nodes()) of
    /// each locally owned cell, in the order of the base element's support
    /// points, and the vertices' linear weights at those points.
    void
    collect_cell_nodes();
    /// Mark the nodes of cells with det(I + grad s) < minimum_jacobian in
    /// @p in_set (ghosted @p shift); returns the number of such cells and
    /// of those inverted (det <= 0) over all ranks and, in @p where, one
    /// of them.
    std::pair<unsigned int, unsigned int>
    mark_inverted(const VectorType  &shift,
                  std::vector<char> &in_set,
                  std::string       *where) const;
    /// One Jacobi sweep over the nodes in @p in_set; returns the new
    /// shift (owned).
    VectorType
    sweep(const VectorType &shift, const std::vector<char> &in_set) const;
    /// A zero vector whose ghost entries can be added to (summed into
    /// their owners by compress(add)).
    VectorType
    writable() const;
    /// Move a node's shift back onto the obstacle if it ends beyond it.
    void
    keep_inside(const dealii::Point<3> &position,
                dealii::Tensor<1, 3>   &shift) const;

    const Discretization                  &discretization;
    const Obstacle                        &obstacle;
    std::vector<std::vector<unsigned int>> cell_nodes;
    std::vector<bool>                      node_fixed; // all three DoFs fixed
    /// weight[b][v]: the linear shape function of vertex v at support
    /// point b of the reference cell.
    std::vector<std::vector<double>> weight;
    unsigned int                     n_vertices = 0;
  };
} // namespace RestShape

#endif
