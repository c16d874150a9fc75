// Carrying the forward problem's state (displacement, rest displacement)
// from one mesh to its refinement, so that an adaptive or global refinement
// cycle starts from the previous cycle's solution instead of from the
// unloaded mesh.
#ifndef restshape_state_transfer_h
#define restshape_state_transfer_h

#include <deal.II/base/point.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/numerics/solution_transfer.h>

#include <restshape/forward/forward_problem.h>

#include <array>
#include <memory>
#include <unordered_map>
#include <vector>

namespace RestShape
{
  /**
   * Usage: construct once the cells are marked and before the mesh changes
   * (LabelledMesh::refine_global() and refine_adaptive() call back at that
   * point), then, after the refinement and ForwardProblem::setup(), call
   * interpolate().
   *
   * Hexahedra: deal.II's SolutionTransfer (p4est's under MPI), which also
   * handles coarsening; hanging nodes and fixed DoFs are set by the forward
   * problem's constraints. Tetrahedra: LabelledMesh rebuilds the
   * triangulation with every tetrahedron red-refined into eight (children
   * of old cell i are new cells 8i..8i+7, on the rank of their parent), so
   * the fields are evaluated at
   * the new nodes from the parent's shape functions; both meshes are affine,
   * so this is exact: the transferred field is the old one.
   */
  class StateTransfer
  {
  public:
    /// Remember @p fields (vectors of @p forward's DoFs, owned or ghosted).
    StateTransfer(const ForwardProblem                  &forward,
                  const std::vector<const VectorType *> &fields);
    ~StateTransfer();

    /// The fields on the refined mesh (owned vectors, constraints applied).
    std::vector<VectorType>
    interpolate(const ForwardProblem &forward);

  private:
    std::vector<VectorType>
    interpolate_tetrahedra(const ForwardProblem &forward) const;

    std::size_t n_fields;
    // Hexahedra. The serial transfer copies the values on prepare; p4est's
    // packs them when the mesh changes (kept alive here until then).
    std::unique_ptr<dealii::SolutionTransfer<3, VectorType>> serial;
    std::unique_ptr<
      dealii::parallel::distributed::SolutionTransfer<3, VectorType>>
                            distributed;
    std::vector<VectorType> inputs;
    // Tetrahedra: every owned old cell's vertices and, per field, its DoF
    // values, by LabelledMesh::cell_index() (the children of a cell stay
    // on its rank), and the number of cells of the whole old mesh.
    struct OldCell
    {
      std::array<dealii::Point<3>, 4> vertices;
      std::vector<double>             values; // field-major
    };
    std::unordered_map<std::size_t, OldCell> old_cells;
    std::size_t                              n_old_cells = 0;
  };
} // namespace RestShape

#endif
