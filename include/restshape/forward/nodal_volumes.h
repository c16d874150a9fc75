// The averaged nodal pressure tetrahedron (Bonet and Burton 1998; the
// linear tetrahedron Joldes, Wittek and Miller use for brain shift): the
// mixed formulation of linear tetrahedra. Each vertex n has the rest
// volume V_n = sum_e V_e / 4 and the current volume v_n = sum_e v_e / 4 of
// the cells around it, one volume ratio J_n = v_n / V_n, and the
// volumetric energy sum_L V_nL U_L(J_n): each label L's energy (K_L/2
// (ln J)^2) on its share V_nL of the rest volume. A cell's pressure is the
// mean of its vertices' sum_L V_nL U_L'(J_n) / V_n, constant on the cell;
// the stiffness couples every DoF of the cells around a vertex. (A volume
// ratio per label and vertex, tried first, locks a layer one cell thick:
// the Lame shell's 2 mm inner label moved 0.40 of the exact cavity
// displacement at nu = 0.4999, 0.91 with one ratio.)
#ifndef restshape_forward_nodal_volumes_h
#define restshape_forward_nodal_volumes_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <restshape/base/linear_algebra_types.h>
#include <restshape/forward/cell_pressures.h>
#include <restshape/material/material_table.h>
#include <restshape/solver/pressure_coupling.h>
#include <restshape/solver/split_tangent.h>

#include <array>
#include <map>
#include <vector>

namespace RestShape
{
  class NodalVolumes
  {
  public:
    /// The locally owned and ghost cells of @p dof_handler (linear
    /// tetrahedra of a 3-component element), for vectors of the layout
    /// of @p like (locally relevant entries).
    /// With @p boundary_to_interior, a boundary vertex's share of each
    /// cell's volume goes to the cell's interior vertices (set_shares()).
    void
    reinit(const dealii::DoFHandler<3> &dof_handler,
           const BufferType            &like,
           const bool                   boundary_to_interior);

    /// Adds to @p dsp the couplings of every DoF of the cells around each
    /// locally owned vertex (the stiffness of its volume), under
    /// @p constraints.
    void
    add_sparsity(dealii::DynamicSparsityPattern          &dsp,
                 const dealii::AffineConstraints<double> &constraints) const;

    /// The vertices' rest volumes per label, and their current ones, at
    /// the state (d, w): the rest position X + w, the current one X + d
    /// (ghosted), and their volume ratios, pressures and stiffnesses
    /// under the laws of @p materials. Collective.
    void
    update(const BufferType    &d,
           const BufferType    &w,
           const MaterialTable &materials);

    /// The vertices' pressure sum_L V_nL U_L'(J_n) / V_n averaged over a
    /// cell (Pa) and the cell's share of the volumetric energy (J); valid
    /// is false where a vertex's volume ratio is not positive.
    struct CellPressure
    {
      double pressure  = 0;
      double energy    = 0;
      double predicted = 0; // the tangent's (record_linearisation())
      bool   valid     = true;
    };

    /// Of the cell of active index @p cell (locally owned), whose rest
    /// volume is @p rest_volume, with its label's law in @p materials.
    CellPressure
    cell(const unsigned int   cell,
         const MaterialTable &materials,
         const double         rest_volume) const;

    /**
     * Record the linearisation of the vertices' pressures at the state of
     * the last update(), whose current positions are X + @p d: each
     * vertex's pressure and stiffness and each cell's volume gradient.
     * The tangents of the states that follow take the pressure the
     * three-field step predicts (as PressurePrediction does for a
     * pressure per cell): p_n0 + k_n0 dv_n, with dv_n the linearised
     * change of the vertex's volume since the record, not the condensed
     * pressure, which carries the bulk modulus times the step's
     * second-order change of volume. Collective.
     */
    void
    record_linearisation(const BufferType &d);
    /// The state jumped (a new rest shape, a load step's start): the
    /// tangent takes the condensed pressure until the next record.
    void
    forget_linearisation()
    {
      known = false;
    }

    /// Each vertex's volume ratio, pressure sum_L V_nL U_L'(J_n) / V_n and
    /// its derivative in J_n at the last update() (its laws), at the local
    /// index of its x-DoF (the other entries zero), without offsets.
    std::vector<PressurePoint>
    pressure_points() const;
    /// The vertices' pressures are shifted by @p offsets (Pa, indexed as
    /// pressure_points(); empty: none), for the three-field tangent of
    /// the direct inverse (ForwardProblem::set_pressure_offsets()).
    void
    set_pressure_offsets(std::vector<double> o)
    {
      offsets = std::move(o);
    }

    /// tangent += sum_L V_nL U_L''(J_n) / V_n^2 g_n g_n^T (g_n = dv_n/dd)
    /// for every locally owned vertex, through @p constraints; each vertex
    /// also into @p coupling, if given (the block preconditioner's), and
    /// as a term of @p split, if given.
    void
    add_stiffness(const BufferType                        &d,
                  const MaterialTable                     &materials,
                  const dealii::AffineConstraints<double> &constraints,
                  dealii::TrilinosWrappers::SparseMatrix  &tangent,
                  BufferType                              &rhs,
                  PressureCoupling                        *coupling = nullptr,
                  SplitTangent *split = nullptr) const;


  private:
    struct Cell
    {
      std::array<dealii::Point<3>, 4>                 vertices;
      std::array<unsigned int, 12>                    local; // [3 v + c]
      std::array<dealii::types::global_dof_index, 12> dofs;  // [3 v + c]
      Label                                           label = 0;
      double orientation = 1; // sign of the mesh cell's volume
      bool   owned       = false;
      // Each vertex's share of the cell's volume: a quarter each (own, or
      // all four vertices on the boundary); with boundary_to_interior,
      // 1 / (the cell's interior vertices) at an interior vertex and 0
      // at a boundary one.
      std::array<double, 4> share = {{0.25, 0.25, 0.25, 0.25}};
    };
    /// The vertex of @p cell whose x-DoF has the local index @p x.
    static unsigned int
    vertex_of(const Cell &cell, const unsigned int x);
    /// Sets the cells' shares from the vertices on the domain's boundary
    /// (the boundary faces of the locally owned cells). Collective.
    void
    set_shares(const dealii::DoFHandler<3> &dof_handler,
               const BufferType            &like);

    /// The positions vertex + @p u of @p cell's vertices.
    static std::array<dealii::Point<3>, 4>
    positions(const Cell &cell, const BufferType &u);

    /// linear_change at the state X + @p d, from the recorded
    /// linearisation. Collective.
    void
    predict_changes(const BufferType &d);

    /// The volume of @p cell at positions(), signed: negative where it
    /// is inverted against the mesh cell.
    static double
    volume(const Cell &cell, const BufferType &u);

    /// dv/du of @p cell at positions(): [3 v + c].
    static std::array<double, 12>
    volume_gradient(const Cell &cell, const BufferType &u);

    /// A vertex's volume ratio, rest volume (m^3), pressure sum_L V_L
    /// U_L'(J) / V (Pa) and stiffness sum_L V_L U_L''(J) / V^2 (Pa/m^6).
    struct Vertex
    {
      double J = 0, rest = 0, pressure = 0, stiffness = 0;
      double predicted = 0; // the tangent's pressure (Pa)
      bool   valid     = false;
    };
    /// Of @p cell's vertex @p v, at the last update().
    /// (The pressure with its offset, if @p shifted.)
    Vertex
    vertex(const Cell        &cell,
           const unsigned int v,
           const bool         shifted = true) const;
    /// The vertex whose x- and y-DoFs have the local indices @p x and
    /// @p y, from the volumes of update(), without offset or prediction.
    Vertex
    evaluate_vertex(const unsigned int   x,
                    const unsigned int   y,
                    const MaterialTable &materials) const;

    std::vector<Cell> cells;   // owned and ghost
    std::vector<int>  of_cell; // active index -> cells, or -1
    // Per locally owned vertex: its x-DoF's local index and the cells
    // around it (indices into cells).
    std::vector<unsigned int>              owned_vertex;
    std::vector<std::vector<unsigned int>> patches;
    // Per label, of that label's cells: at a vertex's x-DoF its rest
    // volume, at its y-DoF its current one (m^3).
    std::map<Label, BufferType> volumes;
    // Per vertex (at its x-DoF's local index, owned and ghost) its
    // evaluate_vertex() at the last update(): the cells around a vertex
    // all read it.
    std::vector<Vertex> evaluated;
    // The linearisation of record_linearisation(): per cell (of cells)
    // its volume gradient and its DoFs' values of d, per vertex (at its
    // x-DoF's local index) its pressure and stiffness; at update() the
    // vertices' linearised changes of volume since then (x-DoF).
    bool                                known = false;
    std::vector<std::array<double, 12>> gradient0, d0;
    std::vector<double>                 pressure0, stiffness0;
    std::vector<double>                 offsets; // set_pressure_offsets()
    BufferType                          linear_change;
  };
} // namespace RestShape

#endif
