// The forward problem: static equilibrium of the body under its load terms
// (load_set.h: body force, surface pressure, elastic support and those of
// the registry), fixed labels (and contact). It is the NewtonSystem that
// its NewtonSolver (newton_solver.h: line search, load stepping) solves.
// Implemented in forward_problem.cc (set-up, state),
// forward_problem_assembly.cc, forward_problem_loads.cc and
// forward_problem_solve.cc (the solves, the tangent's solves); what is
// derived from its state in forward_results.cc.
#ifndef restshape_forward_problem_h
#define restshape_forward_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/thread_local_storage.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <restshape/fem/cell_local_indices.h>
#include <restshape/fem/constraint_lookup.h>
#include <restshape/fem/discretization.h>
#include <restshape/fem/state_reader.h>
#include <restshape/fem/tangent_scatter.h>
#include <restshape/forward/cell_pressures.h>
#include <restshape/forward/forward_parameters.h>
#include <restshape/forward/nodal_volumes.h>
#include <restshape/forward/pressure_prediction.h>
#include <restshape/loads/load_set.h>
#include <restshape/loads/load_state.h>
#include <restshape/loads/load_term.h>
#include <restshape/material/material_table.h>
#include <restshape/mesh/labelled_mesh.h>
#include <restshape/solver/active_set_conditions.h>
#include <restshape/solver/active_set_constraints.h>
#include <restshape/solver/linear_solver.h>
#include <restshape/solver/newton_solver.h>
#include <restshape/solver/newton_system.h>
#include <restshape/solver/pressure_coupling.h>
#include <restshape/solver/split_tangent.h>
#include <restshape/solver/tangent_strategy.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace RestShape
{

  /**
   * The forward problem. It owns its discretisation (discretization()) and
   * its load terms (loads()), and is the NewtonSystem (privately: only its
   * NewtonSolver calls that protocol) that its NewtonSolver solves. What
   * is derived from its state (norms, forces, stresses) are free functions
   * (forward_results.h).
   */
  class ForwardProblem : public StateReader, private NewtonSystem
  {
  public:
    ForwardProblem(const ForwardParameters    &parameters,
                   LabelledMesh               &mesh,
                   const MaterialTable        &materials,
                   dealii::TimerOutput        &timer,
                   dealii::ConditionalOStream &pcout);
    ~ForwardProblem() override;

    /// Distribute DoFs, build constraints and the matrix; zero state.
    void
    setup();
    /// Optional contact (owned by the caller; nullptr: none). Its setup()
    /// must follow setup().
    void
    set_contact(ActiveSetConstraints *contact);

    /**
     * Move the equilibrium from the current state (an equilibrium of the
     * current load and rest shape, e.g. the unloaded state after setup())
     * to @p load with rest displacement @p rest (owned vector). Increments
     * are halved when Newton fails. The state is left at the last
     * equilibrium reached.
     */
    SolveStatistics
    solve(const LoadState &load, const VectorType &rest);
    /**
     * Equilibrium under @p load with rest displacement @p rest (owned
     * vectors) by Newton's method at the full load from the displacement
     * @p guess (e.g. the previous refinement cycle's solution); if that
     * fails, or without a guess (nullptr), solve() from the unloaded state
     * (contact released). The statistics count both attempts.
     */
    SolveStatistics
    solve_from(const VectorType *guess,
               const LoadState  &load,
               const VectorType &rest);

    // --- what it is made of --------------------------------------------
    /// The finite element space, its DoFs, nodes and base constraints.
    const Discretization &
    discretization() const
    {
      return discretization_;
    }
    /// The scene's load terms (after setup()): its load
    /// (LoadSet::scene_load()), a scenario's change and openings.
    const LoadSet &
    loads() const
    {
      return load_set;
    }
    LoadSet &
    loads()
    {
      return load_set;
    }
    const MaterialTable &
    materials() const;
    /// The scene's parameters of the forward problem.
    const ForwardParameters &
    scene_parameters() const
    {
      return parameters;
    }
    /// The linear solver in use (Linear solver = auto resolved by size).
    LinearSolverType
    linear_solver_kind() const
    {
      return linear_solver_type;
    }

    // --- state ---------------------------------------------------------
    /// Equilibrium displacement from the mesh geometry (ghosted, m).
    const VectorType &
    displacement() const override;
    /// Rest displacement X_rest - X_mesh (ghosted, m).
    const VectorType &
    rest_displacement() const override;
    const LoadState &
    load() const;
    /// Set the state (owned vectors); the caller vouches for equilibrium.
    void
    set_state(const VectorType &d, const VectorType &w, const LoadState &l);

    /**
     * Total potential energy of the last assembled state (after solve():
     * the final state), in J: the strain energy over the rest shape, plus
     * the elastic support's k/2 |d - w|^2 over its faces, minus the work
     * f_ext . (d - w) of the dead loads (gravity, CSF pressure) from the
     * rest shape. Zero in the rest shape; Newton's residual is its negative
     * gradient. A stable equilibrium is a local minimum: of two equilibria
     * of the same scene and mesh, the one with the lower energy is the one
     * the body prefers. NaN after set_state() until the next assembly.
     */
    double
    potential_energy() const;
    /**
     * f_ext - f_int at the last assembled state (after solve(): the final
     * state), condensed only for hanging nodes: at fixed DoFs it is minus
     * the support reaction, at contact nodes minus the contact force (N).
     */
    const VectorType &
    raw_residual() const override;
    /// The residual of the last assembly with the Newton constraints
    /// condensed (external minus internal forces, N; zero at constrained
    /// DoFs, owned).
    const VectorType &
    condensed_residual() const override
    {
      return residual_condensed;
    }
    /**
     * Assemble the raw residual at the current state (for the direct
     * inverse, tests and diagnostics) and, with @p tangent, the tangent
     * (Dirichlet rows condensed). Returns false if a cell is inverted.
     */
    bool
    evaluate(const bool tangent = false);
    /// The tangent of the last evaluate(true) or Newton step.
    const MatrixType &
    tangent_matrix() const;
    /// Mixed formulation on linear tetrahedra: the vertices' volumes at
    /// the current state, for nodal_cell_pressure(). Collective.
    void
    update_nodal_volumes() const;
    /// The pressure -U'(J) of the owned cell of active index @p cell,
    /// averaged over its vertices, at update_nodal_volumes()' state (Pa).
    double
    nodal_cell_pressure(const unsigned int cell) const;
    /**
     * Mixed formulation: the state of each point that carries a pressure
     * (a cell with a pressure of its own, by active cell index: its mean
     * dilatation, U'(J_mean), U''(J_mean); a vertex of the averaged nodal
     * pressure, by the local index of its x-DoF in the assembly's
     * vectors: its volume ratio, its pressure and the derivative), at the
     * last assembly. Only the locally owned cells' and the locally
     * relevant vertices' entries are meaningful.
     */
    std::vector<PressurePoint>
    pressure_points() const;
    /**
     * Mixed formulation: from now on the assembly uses U' + @p offsets
     * (Pa, indexed as pressure_points()) as the pressure of each point, in
     * the residual and the tangent, so that the derivative of the
     * residual at the state the offsets were taken at is the three-field
     * tangent with the pressures U' + offsets (cell_pressures.h); empty:
     * the condensed pressures again.
     */
    void
    set_pressure_offsets(std::vector<double> offsets);
    /// The contact conditions checked at the end of the last Newton solve
    /// with contact (ActiveSetConstraints::check_conditions()).
    const ContactConditions &
    contact_conditions() const
    {
      return newton_solver.contact_conditions();
    }

    // --- solves with the tangent of the current state ------------------
    /**
     * For solves with the tangent of the current state (stability check,
     * direct inverse): assemble the consistent tangent (whatever
     * Discretization/Tangent says) with the constraints of the last Newton
     * step and prepare solves with it: the direct solver factorises it,
     * CG + AMG sets up (or keeps, lagged) its AMG.
     */
    void
    prepare_consistent_tangent();
    /// Solve K x = b with the tangent of prepare_consistent_tangent():
    /// exactly with the direct solver, with CG + AMG to the relative
    /// tolerance @p tolerance.
    void
    solve_with_tangent(
      VectorType       &x,
      const VectorType &b,
      const double      tolerance = LinearSolver::prepared_solve_tolerance);
    /// Whether solve_with_tangent() solves exactly (the direct solver).
    bool
    tangent_solves_are_exact() const;
    /// Free the linear solver's factorisation or AMG (the next solve builds
    /// them again): on large meshes they are the largest part of the memory,
    /// and the postprocessing (the error estimator) needs memory too.
    void
    release_linear_solver();
    /// The constraints of the last Newton step (fixed DoFs, hanging nodes,
    /// active contact).
    const dealii::AffineConstraints<double> &
    newton_constraints() const
    {
      return constraints_newton;
    }

  private:
    // --- NewtonSystem (newton_system.h): its NewtonSolver's protocol ----
    VectorType &
    unknowns() override
    {
      return d;
    }
    const VectorType &
    ghosted_unknowns() const override
    {
      return d_ghost;
    }
    void
    unknowns_changed() override
    {
      d_ghost = d;
    }
    const dealii::AffineConstraints<double> &
    make_step_constraints() override;
    void
    set_tangent_type(const TangentType type) override
    {
      tangent_type = type;
    }
    bool
    assemble_residual() override;
    bool
    assemble_step() override;
    const VectorType &
    external_forces() const override
    {
      return external_condensed;
    }
    double
    energy() const override
    {
      return total_energy;
    }
    MatrixType &
    step_matrix() override
    {
      return tangent;
    }
    const VectorType &
    step_rhs() const override
    {
      return rhs_newton;
    }
    Assembled
    assembled() const override;
    void
    restore(const Assembled &a) override;
    void
    unknowns_restarted() override;
    double
    resolution() const override;
    std::string
    inverted_cells_text() const override;
    std::string
    compression_text() const override;

    /// Linear solver = auto: direct or cg-amg by the number of DoFs.
    LinearSolverType
    resolve_linear_solver() const;
    /// The narrow matrix of split_tangent, from the cells' couplings.
    void
    setup_split_tangent();
    struct ScratchData;
    struct CopyData;
    struct CellVolumetric;
    enum class Assemble
    {
      residual,
      residual_and_matrix,
      /// The residual, and into magnitude_buffer the sum of the absolute
      /// values of its internal and body-force terms (their round-off).
      residual_and_magnitudes
    };

    /// The load terms the scene enables (ForwardParameters::load_terms).
    /// Throws InputError if the fluid wets no pressure face.
    void
    setup_load_terms();
    void
    compute_rigid_body_modes();

    /**
     * Assemble at the state (ghosted_d, ghosted_w, current_load): the raw
     * residual f_ext - f_int (base constraints), the condensed residual (all
     * constraints, homogeneous) and, if asked, the tangent and the Newton
     * right-hand side (with contact inhomogeneities). Returns false if
     * det F <= 0 somewhere.
     */
    bool
    assemble(const Assemble what);

    void
    local_assemble(
      const typename dealii::DoFHandler<3>::active_cell_iterator &cell,
      ScratchData                                                &scratch,
      CopyData                                                   &copy,
      const Assemble                                              what) const;
    /// The mixed formulation's pressures of the cell being assembled
    /// (rest volume @p V, int J dV_rest @p J_volume; with a linear
    /// pressure, @p scratch's modes reinit for it), its volumetric energy
    /// added to @p copy; false where its volumes are not admissible.
    bool
    cell_volumetric(ScratchData       &scratch,
                    CopyData          &copy,
                    const MaterialLaw &law,
                    const double       V,
                    const double       J_volume,
                    const bool         matrix,
                    CellVolumetric    &vol) const;
    /// Record the cell's pressure linearisation (PressurePrediction) from
    /// the volume gradients in @p scratch's ElasticCell: the condensed
    /// pressures of its modes and their derivatives (m x m).
    void
    record_pressure_linearisation(ScratchData       &scratch,
                                  const unsigned int cell,
                                  const double      *pressures,
                                  const double      *derivatives) const;
    /// The cell's condensed pressure unknowns for PressureCoupling: its
    /// volumetric stiffness sum_ab @p stiffness_ab G_a G_b^T (the volume
    /// gradients in @p scratch's ElasticCell) as outer products, of which
    /// the pressure block takes @p fraction (coupled_fraction()).
    void
    coupling_rows(ScratchData                      &scratch,
                  const double                      fraction,
                  const dealii::FullMatrix<double> &stiffness,
                  CopyData                         &copy) const;

    const ForwardParameters    &parameters;
    Discretization              discretization_;
    const MaterialTable        &material_table;
    dealii::TimerOutput        &timer;
    dealii::ConditionalOStream &pcout;
    LinearSolverType            linear_solver_type = LinearSolverType::direct;

    dealii::AffineConstraints<double> constraints_newton; // + contact

    MatrixType     tangent;
    TangentScatter scatter; // of the cells' matrices into tangent
    // The averaged nodal pressure's tangent split for CG + AMG (set up if
    // splits_tangent): the cells' matrices go into its narrow matrix, the
    // vertices' terms into it and tangent, which then gets the cells' too.
    SplitTangent split_tangent;
    bool         splits_tangent = false;
    // The three constraint sets by the buffers' local indices (set at
    // each assembly) and the cells' local indices (set up with the DoFs).
    ConstraintLookup lookup_hanging, lookup_base, lookup_newton;
    CellLocalIndices cell_local_indices;
    // Each thread's assembly workspace, kept from one assembly to the next:
    // building its FEValues and FEFaceValues costs as much as assembling
    // a thousand P1 cells.
    dealii::Threads::ThreadLocalStorage<std::shared_ptr<ScratchData>>
      thread_scratch;
    ScratchData            &
    scratch_of_this_thread();
    VectorType rhs_newton, residual_raw, residual_condensed, external_condensed;
    VectorType d, d_ghost, w, w_ghost;
    // The assembly reads d and w from, and adds into, deal.II's distributed
    // vectors (locally relevant entries, element access by an index
    // shift), then copies the sums into the Trilinos vectors above.
    BufferType d_buffer, w_buffer;
    // Mixed formulation on linear tetrahedra: the vertices' volumes of
    // the last assembly (or of nodal_cell_pressure()'s state).
    mutable NodalVolumes nodal_volumes;
    // Mixed formulation with a pressure per cell: the linearisation of
    // each cell's pressure at the last tangent, for the next tangent.
    mutable PressurePrediction pressure_prediction;
    // ... and the cells' dilatations of the last assembly, with the
    // pressure offsets a caller set (set_pressure_offsets()).
    mutable CellPressures cell_pressures;
    BufferType raw_buffer, condensed_buffer, external_buffer, rhs_buffer,
      magnitude_buffer;
    double total_energy = 0; // of the last assembly (J)
    // The last assembly that met an inverted cell (det F or det G <= 0 at
    // a quadrature point): how many, one of them (label, centre in the
    // mesh, m), over all ranks. Others leave it as it is.
    struct InvertedCells
    {
      unsigned int               count = 0;
      dealii::Point<3>           center;
      dealii::types::material_id label = 0;
    } inverted_cells;
    // Tangent of the next assembly (Tangent = adaptive switches it).
    TangentType tangent_type = TangentType::consistent;
    LoadState   current_load;
    /// body_force_varies(current_load), set at each assembly.
    bool current_body_force_varies = false;
    /// Whether the tangent assemblies keep the condensed pressure unknowns
    /// (pressure_coupling) for the block preconditioner: set at setup.
    bool             records_coupling = false;
    PressureCoupling pressure_coupling;

    LoadSet load_set; // setup_load_terms()

    std::unique_ptr<LinearSolver> linear_solver;
    ActiveSetConstraints         *contact = nullptr;
    NewtonSolver                  newton_solver;
  };
} // namespace RestShape

#endif
