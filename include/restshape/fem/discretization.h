// The discretisation of the forward problem: the finite element space on
// the mesh (P1/P2 tetrahedra, Q1/Q2 hexahedra), its quadrature, DoFs and
// nodes, the hanging-node and fixed-label constraints, and vectors of its
// layout: what contact, the inverse problem and the postprocessing need of
// the forward problem besides its state.
#ifndef restshape_fem_discretization_h
#define restshape_fem_discretization_h

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <restshape/base/linear_algebra_types.h>
#include <restshape/fem/discretization_parameters.h>
#include <restshape/mesh/labelled_mesh.h>

#include <array>
#include <memory>
#include <vector>

namespace RestShape
{
  /// "label 1 at (x, y, z) mm of the mesh": where a cell is (@p center in m).
  std::string
  cell_location_text(const dealii::types::material_id label,
                     const dealii::Point<3>          &center);

  /// A mesh node: its three displacement DoFs and its mesh position (m).
  struct Node
  {
    std::array<dealii::types::global_dof_index, 3> dofs;
    dealii::Point<3>                               position;
  };

  class Discretization
  {
  public:
    /// The element and quadrature of Discretization/Polynomial degree on
    /// @p mesh; setup_dofs() distributes the DoFs.
    Discretization(const DiscretizationParameters &parameters,
                   LabelledMesh                   &mesh);
    ~Discretization();

    /// Distribute DoFs, find the nodes, build the hanging-node and
    /// fixed-label constraints (for the current mesh).
    void
    setup_dofs();

    const dealii::DoFHandler<3> &
    dof_handler() const;
    const dealii::Mapping<3> &
    mapping() const;
    const dealii::FESystem<3> &
    fe() const;
    const dealii::Quadrature<3> &
    quadrature() const
    {
      return cell_quadrature;
    }
    const dealii::Quadrature<2> &
    face_quadrature() const;
    /// Hanging nodes and fixed labels.
    const dealii::AffineConstraints<double> &
    base_constraints() const;
    /// Hanging nodes only.
    const dealii::AffineConstraints<double> &
    hanging_constraints() const
    {
      return constraints_hanging;
    }
    /// Discretization and Boundary conditions/Fixed labels.
    const DiscretizationParameters &
    parameters() const
    {
      return settings;
    }
    /// The communicator of the mesh.
    MPI_Comm
    communicator() const
    {
      return comm;
    }
    const dealii::IndexSet &
    locally_owned_dofs() const;
    const dealii::IndexSet &
    locally_relevant_dofs() const;
    /// Locally owned nodes (all support points, vertices and for degree 2
    /// edge/face/cell nodes), with their mesh positions.
    const std::vector<Node> &
    owned_nodes() const;
    /// Nodes of locally owned and ghost cells.
    const std::vector<Node> &
    relevant_nodes() const;
    bool
    is_fixed(const dealii::types::global_dof_index dof) const;
    /// Whether @p dof is fixed, or a hanging DoF whose constraint involves
    /// fixed DoFs only.
    bool
    is_held(const dealii::types::global_dof_index dof) const;
    /// Whether some node is fixed in x, y, z (over all ranks).
    std::array<bool, 3>
    fixed_components() const;
    const LabelledMesh &
    mesh() const;

    /// A zero owned vector with the DoF layout.
    VectorType
    zero_vector() const;
    /// An owned copy of @p v (owned or ghosted): Trilinos adds, subtracts
    /// and compares only vectors of the same layout.
    VectorType
    owned_copy(const VectorType &v) const;
    /// A ghosted copy of the owned vector @p v (read access to the values
    /// at the locally relevant DoFs).
    VectorType
    ghosted_copy(const VectorType &v) const;
    /**
     * A displacement-like field from values at the mesh vertices (indexed
     * by triangulation vertex), interpolated linearly (P1/Q1) into the
     * finite element space (owned vector).
     */
    VectorType
    interpolate_vertex_field(
      const std::vector<dealii::Tensor<1, 3>> &values) const;
    /// weights[b][v]: the linear (P1/Q1) shape function of the cell's
    /// vertex v at the support point b of the base element: a node's value
    /// interpolated linearly from the vertices.
    std::vector<std::vector<double>>
    vertex_weights() const;
    /// Smallest det(I + grad w) over the quadrature points of the cell on
    /// which @p fe_values (gradients) was last reinitialised; @p w ghosted.
    static double
    smallest_jacobian(const dealii::FEValues<3> &fe_values,
                      const VectorType          &w);

  protected:
    const DiscretizationParameters &settings;
    LabelledMesh                   &labelled_mesh;
    const MPI_Comm                  comm;

    std::unique_ptr<dealii::Mapping<3>> mapping_;
    dealii::FESystem<3>                 fe_;
    dealii::Quadrature<3>               cell_quadrature;
    dealii::Quadrature<2>               face_quadrature_;
    dealii::DoFHandler<3>               dof_handler_;
    dealii::IndexSet                    owned_dofs, relevant_dofs;
    dealii::AffineConstraints<double>   constraints_hanging;
    dealii::AffineConstraints<double>   constraints_base; // hanging + fixed
    std::vector<bool>                   fixed_dof;        // relevant dofs
    std::vector<Node>                   owned_nodes_, relevant_nodes_;

  private:
    void
    setup_nodes();
    void
    setup_constraints();
    /// Fixed boundary planes: hold the listed components of the DoFs of
    /// @p cell's boundary faces that lie in a plane.
    void
    add_plane_constraints(
      const dealii::DoFHandler<3>::active_cell_iterator &cell);
  };
} // namespace RestShape

#endif
