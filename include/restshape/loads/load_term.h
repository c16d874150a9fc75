// A load term: one external load of the forward problem (a body force, a
// surface pressure, an elastic support, a traction), with its residual,
// tangent, potential and resultant, its load in the scene and what a
// scenario changes of it. The forward problem's assembly sums the terms
// (load_set.h); a new load is a class derived from LoadTerm and one line
// in the registry (load_registry.h).
#ifndef restshape_loads_load_term_h
#define restshape_loads_load_term_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

#include <restshape/base/linear_algebra_types.h>
#include <restshape/base/region.h>
#include <restshape/fem/local_field.h>
#include <restshape/fem/simplex_face_values.h>
#include <restshape/loads/load_state.h>
#include <restshape/loads/scenario_change.h>
#include <restshape/material/material_table.h>
#include <restshape/mesh/labelled_mesh.h>

#include <functional>
#include <memory>
#include <set>
#include <vector>

namespace RestShape
{
  using CellIterator = dealii::DoFHandler<3>::active_cell_iterator;

  /// What a load term is built on: the mesh and its discretisation.
  struct LoadContext
  {
    const LabelledMesh          &mesh;
    const MaterialTable         &materials;
    const dealii::Mapping<3>    &mapping;
    const dealii::FESystem<3>   &fe;
    const dealii::Quadrature<2> &face_quadrature;
    const dealii::DoFHandler<3> &dof_handler;
    MPI_Comm                     comm;
    /// Whether a DoF is fixed, or a hanging DoF of fixed DoFs only.
    std::function<bool(dealii::types::global_dof_index)> is_held;
    /// Whether every component of a label is fixed.
    std::function<bool(Label)> fully_fixed;
    /// The scenario entries (ScenarioEntry) that some scenario of the run
    /// sets to a value other than zero.
    std::set<std::string> set_later;
    /// Parts of the surface that a term made earlier carries alone (e.g.
    /// the cavity walls, under their own pressure): the terms made later
    /// leave them out. Shared by the terms of one LoadSet.
    std::shared_ptr<std::set<std::string>> claimed_surfaces =
      std::make_shared<std::set<std::string>>();

    /// The labels @p given, or every label of the mesh not fully fixed.
    std::set<Label>
    labels_or_unfixed(const std::set<Label> &given) const;
  };

  class LoadTerm;
  /// Makes a load term from its parameters' values on a discretisation.
  using LoadTermFactory =
    std::function<std::unique_ptr<LoadTerm>(const LoadContext &)>;

  /// Call @p f(cell, face) for every boundary face of the locally owned
  /// cells (with @p ghosts: of the owned and ghost cells) of @p labels.
  template <typename Function>
  void
  for_each_boundary_face(const dealii::DoFHandler<3> &dof_handler,
                         const LabelledMesh          &mesh,
                         const std::set<Label>       &labels,
                         Function                   &&f,
                         const bool                   ghosts = false)
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if ((ghosts ? !cell->is_artificial() : cell->is_locally_owned()) &&
          labels.count(cell->material_id()))
        for (const unsigned int face : cell->face_indices())
          if (mesh.at_surface(*cell, face))
            f(cell, face);
  }

  /// Per-thread workspace of the face terms (sized for one cell). The
  /// load terms of one cell share it: it is set on a face once, with the
  /// state's values and gradients there. Its FEFaceValues (on affine
  /// tetrahedra its SimplexFaceValues, the same numbers) are of the scalar
  /// base element; shape_value() and shape_grad() take the vector
  /// element's shape functions.
  struct FaceScratch
  {
    FaceScratch(const dealii::Mapping<3>       &mapping,
                const dealii::FiniteElement<3> &fe,
                const dealii::Quadrature<2>    &face_quadrature);
    FaceScratch(const FaceScratch &other);

    /// Set on face @p f of @p cell with d and w there, unless it already
    /// is (since the last forget()).
    void
    reinit(const CellIterator &cell,
           const unsigned int  f,
           const LocalField   &d,
           const LocalField   &w);

    /// A new cell or state: no face is current.
    void
    forget()
    {
      current_face = dealii::numbers::invalid_unsigned_int;
    }

    /// Shape function @p i of the vector element (its nonzero component)
    /// at point @p q.
    double
    shape_value(const unsigned int i, const unsigned int q) const
    {
      return scalar_shape_value(scalar[i], q);
    }
    const dealii::Tensor<1, 3> &
    shape_grad(const unsigned int i, const unsigned int q) const
    {
      return scalar_shape_grad(scalar[i], q);
    }
    /// Shape function @p k of the scalar element at point @p q.
    double
    scalar_shape_value(const unsigned int k, const unsigned int q) const
    {
      return simplex ? simplex->shape_value(k, q) :
                       fe_face_values.shape_value(k, q);
    }
    const dealii::Tensor<1, 3> &
    scalar_shape_grad(const unsigned int k, const unsigned int q) const
    {
      return simplex ? simplex->shape_grad(k, q) :
                       fe_face_values.shape_grad(k, q);
    }
    /// The scalar element's number of shape functions.
    unsigned int
    n_scalar_functions() const
    {
      return fe_face_values.get_fe().n_dofs_per_cell();
    }
    double
    JxW(const unsigned int q) const
    {
      return simplex ? simplex->JxW(q) : fe_face_values.JxW(q);
    }
    const dealii::Tensor<1, 3> &
    normal_vector(const unsigned int q) const
    {
      return simplex ? simplex->normal_vector(q) :
                       fe_face_values.normal_vector(q);
    }
    const dealii::Point<3> &
    quadrature_point(const unsigned int q) const
    {
      return simplex ? simplex->quadrature_point(q) :
                       fe_face_values.quadrature_point(q);
    }
    auto
    quadrature_point_indices() const
    {
      return fe_face_values.quadrature_point_indices();
    }

    const dealii::FiniteElement<3> &fe; // the vector element
    dealii::FEFaceValues<3>         fe_face_values;
    /// On affine tetrahedra, what is used in place of fe_face_values.
    std::unique_ptr<SimplexFaceValues> simplex;
    std::vector<dealii::Tensor<1, 3>>  face_d, face_w;
    std::vector<Tensor2>               face_grad_d, face_grad_w;
    dealii::FullMatrix<double>         face_matrix;

  private:
    std::vector<unsigned int> scalar; // base function of shape function i
    unsigned int current_face = dealii::numbers::invalid_unsigned_int;
  };

  /// One cell of the assembly as a load term sees it: the state (d, w:
  /// displacement and rest displacement, m, on this cell), the load, and
  /// where its contributions go.
  struct LoadCell
  {
    const CellIterator &cell;
    const LocalField   &d, &w;
    const LoadState    &load;
    const bool          matrix; // whether the tangent is assembled
    FaceScratch        &scratch;

    dealii::FullMatrix<double> &cell_matrix; // + d(f_int - f_ext)/du
    dealii::Vector<double>     &cell_rhs;    // + f_ext
    dealii::Vector<double>     &cell_external;
    double                     &energy; // + the term's own potential (J)

    /// The face scratch set on face @p f of this cell.
    const FaceScratch &
    face(const unsigned int f) const
    {
      scratch.reinit(cell, f, d, w);
      return scratch;
    }
  };

  /**
   * One external load. A term adds a body force (per unit volume of the
   * mesh geometry, evaluated in the elastic assembly's quadrature loop)
   * and/or its face terms. A dead term's potential is -f_ext . (d - w),
   * which the assembly adds from its cell_external; a term that is not
   * dead (a follower pressure, a support) adds its own to the energy.
   */
  class LoadTerm
  {
  public:
    virtual ~LoadTerm() = default;

    /// Add the term's load in the scene (its parameters' values, weight 1)
    /// to @p load.
    virtual void
    scene_load(LoadState &) const
    {}
    /// A scenario's change of the term's load: @p changed holds the
    /// scene's load (and the changes of the terms before); change what the
    /// scenario @p change changes of this term (gravity turned, the fluid
    /// drained to a level, the values of the term's scenario entries).
    virtual void
    change_load(const ScenarioChange &, LoadState &) const
    {}
    /// What a scenario's opening of the skull takes off the term's load,
    /// once every term has changed @p changed.
    virtual void
    open_load(const ScenarioChange &, LoadState &) const
    {}
    /// "surface pressure 10 -> 0 Pa": how the term's load changed from
    /// @p scene to @p changed, for the screen; empty if it did not.
    virtual std::string
    change_text(const LoadState &, const LoadState &) const
    {
      return "";
    }
    /// An opening of the skull: the term's faces centred in it change as
    /// open_load() says (a follower tangent may turn non-symmetric).
    /// Returns their number (over all ranks). An empty region closes it.
    virtual unsigned int
    open(const Region &)
    {
      return 0;
    }

    /// Whether its potential is the work of a force that does not depend
    /// on the state (a dead load): the assembly then adds it.
    virtual bool
    dead() const
    {
      return true;
    }
    /// Whether body_force() is not zero.
    virtual bool
    has_body_force() const
    {
      return false;
    }
    /// Whether the body force of @p load varies within a cell.
    virtual bool
    body_force_varies(const LoadState &) const
    {
      return false;
    }
    /// The body force per unit mesh volume (N/m^3) at @p X of @p cell.
    virtual dealii::Tensor<1, 3>
    body_force(const dealii::CellAccessor<3, 3> &,
               const dealii::Point<3> &,
               const LoadState &) const
    {
      return {};
    }
    /// Add the face terms of @p c.cell: residual, external force, tangent
    /// (if c.matrix) and, unless dead(), their potential.
    virtual void
    assemble_faces(const LoadCell &) const
    {}
    /// Resultant (N) of the face force under @p load at the state @p d,
    /// @p w (ghosted), over the locally owned cells.
    virtual dealii::Tensor<1, 3>
    local_resultant(const LoadState &,
                    const VectorType &,
                    const VectorType &) const
    {
      return {};
    }
    /// Whether the term is a support that holds the body (its resultant a
    /// reaction, not an applied load).
    virtual bool
    is_support() const
    {
      return false;
    }
    /// Whether its assembled tangent is symmetric.
    virtual bool
    symmetric() const
    {
      return true;
    }
  };
} // namespace RestShape

#endif
