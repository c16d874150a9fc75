// ForwardProblem: set-up (the discretisation's DoFs, the matrix, the
// vectors, the linear solver, rigid-body modes) and state. Assembly is in
// forward_problem_assembly.cc, the load terms in forward_problem_loads.cc,
// the solves in forward_problem_solve.cc (Newton: newton_solver.cc), the
// results (norms, stresses, forces, energy) in forward_problem_results.cc.

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <restshape/base/input_error.h>
#include <restshape/forward/forward_problem.h>

#include <cmath>
#include <limits>

namespace RestShape
{
  using namespace dealii;

  // ------------------------------------------------------------------

  ForwardProblem::ForwardProblem(const ForwardParameters &parameters,
                                 LabelledMesh            &mesh,
                                 const MaterialTable     &materials,
                                 TimerOutput             &timer,
                                 ConditionalOStream      &pcout)
    : parameters(parameters)
    , discretization_(parameters.discretization, mesh)
    , material_table(materials)
    , timer(timer)
    , pcout(pcout)
    , tangent_type(parameters.discretization.tangent == TangentType::adaptive ?
                     TangentType::consistent :
                     parameters.discretization.tangent)
    , newton_solver(*this,
                    parameters.solver,
                    parameters.discretization.tangent,
                    timer,
                    pcout)
  {}

  ForwardProblem::~ForwardProblem() = default;

  void
  ForwardProblem::set_contact(ActiveSetConstraints *c)
  {
    contact = c;
    newton_solver.set_contact(c);
  }

  void
  ForwardProblem::setup()
  {
    TimerOutput::Scope scope(timer, "Setup");
    // The solver's factorisation refers to the old matrix: release it first.
    linear_solver.reset();
    discretization_.setup_dofs();
    make_step_constraints();

    DynamicSparsityPattern dsp(discretization_.locally_relevant_dofs());
    DoFTools::make_sparsity_pattern(discretization_.dof_handler(),
                                    dsp,
                                    discretization_.base_constraints(),
                                    true);
    if (parameters.discretization.nodal_pressure)
      {
        // Its layout: the buffers' (set up below, the same).
        BufferType like(discretization_.locally_owned_dofs(),
                        discretization_.locally_relevant_dofs(),
                        discretization_.communicator());
        nodal_volumes.reinit(
          discretization_.dof_handler(),
          like,
          parameters.discretization.boundary_shares_to_interior);
        nodal_volumes.add_sparsity(dsp, discretization_.base_constraints());
      }
    if (parameters.discretization.mixed)
      {
        const unsigned int n_cells =
          discretization_.dof_handler().get_triangulation().n_active_cells();
        const unsigned int modes =
          parameters.discretization.cell_pressure_modes();
        pressure_prediction.reset(n_cells,
                                  discretization_.fe().n_dofs_per_cell(),
                                  modes);
        if (!parameters.discretization.nodal_pressure)
          cell_pressures.reset(n_cells * modes);
      }
    SparsityTools::distribute_sparsity_pattern(
      dsp,
      discretization_.locally_owned_dofs(),
      discretization_.communicator(),
      discretization_.locally_relevant_dofs());
    tangent.reinit(discretization_.locally_owned_dofs(),
                   discretization_.locally_owned_dofs(),
                   dsp,
                   discretization_.communicator());
    scatter.forget();

    for (VectorType *v : {&rhs_newton,
                          &residual_raw,
                          &residual_condensed,
                          &external_condensed,
                          &d,
                          &w})
      v->reinit(discretization_.locally_owned_dofs(),
                discretization_.communicator());
    d_ghost.reinit(discretization_.locally_owned_dofs(),
                   discretization_.locally_relevant_dofs(),
                   discretization_.communicator());
    w_ghost.reinit(discretization_.locally_owned_dofs(),
                   discretization_.locally_relevant_dofs(),
                   discretization_.communicator());
    // The buffers copy into the Trilinos vectors entry by entry: both store
    // the owned entries in the order of their (contiguous) global indices.
    AssertThrow(discretization_.locally_owned_dofs().is_contiguous(),
                ExcMessage("the locally owned DoFs are not contiguous"));
    for (BufferType *b : {&d_buffer,
                          &w_buffer,
                          &raw_buffer,
                          &condensed_buffer,
                          &external_buffer,
                          &rhs_buffer,
                          &magnitude_buffer})
      b->reinit(discretization_.locally_owned_dofs(),
                discretization_.locally_relevant_dofs(),
                discretization_.communicator());
    cell_local_indices.reinit(discretization_.dof_handler(),
                              *raw_buffer.get_partitioner());
    current_load = LoadState();

    setup_load_terms();

    SolverParameters solver = parameters.solver;
    solver.linear_solver    = resolve_linear_solver();
    linear_solver_type      = solver.linear_solver;
    linear_solver =
      std::make_unique<LinearSolver>(solver,
                                     parameters.discretization.degree,
                                     &timer);
    linear_solver->set_symmetric(load_set.symmetric());
    // auto's choice is a matter of speed: where CG + AMG fails, the direct
    // solver, which it would have taken on a smaller mesh, takes over.
    if (parameters.solver.linear_solver == LinearSolverType::automatic &&
        linear_solver_type == LinearSolverType::cg_amg)
      linear_solver->allow_direct_fallback();
    if (linear_solver_type == LinearSolverType::cg_amg)
      compute_rigid_body_modes();
    records_coupling =
      linear_solver_type == LinearSolverType::cg_amg &&
      parameters.discretization.mixed &&
      parameters.solver.mixed_preconditioner == MixedPreconditioner::block;
    if (records_coupling)
      pcout << "Linear solver: the block preconditioner of the mixed "
               "formulation (Solver/Mixed preconditioner)"
            << std::endl;
    linear_solver->set_pressure_coupling(records_coupling ? &pressure_coupling :
                                                            nullptr);
    splits_tangent = parameters.discretization.nodal_pressure &&
                     linear_solver_type == LinearSolverType::cg_amg &&
                     !records_coupling && parameters.solver.split_nodal_tangent;
    if (splits_tangent)
      setup_split_tangent();
    linear_solver->set_split_tangent(splits_tangent ? &split_tangent : nullptr);
    newton_solver.setup(linear_solver.get(), linear_solver_type);
  }

  void
  ForwardProblem::setup_split_tangent()
  {
    // The cells' couplings alone, as the displacement formulation's.
    DynamicSparsityPattern narrow(discretization_.locally_relevant_dofs());
    DoFTools::make_sparsity_pattern(discretization_.dof_handler(),
                                    narrow,
                                    discretization_.base_constraints(),
                                    true);
    SparsityTools::distribute_sparsity_pattern(
      narrow,
      discretization_.locally_owned_dofs(),
      discretization_.communicator(),
      discretization_.locally_relevant_dofs());
    split_tangent.reinit(discretization_.locally_owned_dofs(),
                         narrow,
                         discretization_.communicator());
  }

  LinearSolverType
  ForwardProblem::resolve_linear_solver() const
  {
    if (parameters.solver.linear_solver != LinearSolverType::automatic)
      return parameters.solver.linear_solver;
    const types::global_dof_index n = discretization_.dof_handler().n_dofs();
    const unsigned int            degree = parameters.discretization.degree;
    const unsigned int            limit  = auto_direct_dofs(degree);
    // A direction that no fixed label holds leaves the tangent singular
    // until contact or the support acts: CG cannot solve that, the direct
    // solver can.
    const std::array<bool, 3> held     = discretization_.fixed_components();
    const bool                all_held = held[0] && held[1] && held[2];
    const LinearSolverType    chosen   = n <= limit || !all_held ?
                                           LinearSolverType::direct :
                                           LinearSolverType::cg_amg;
    pcout << "Linear solver: auto chose "
          << (chosen == LinearSolverType::direct ? "direct" : "cg-amg")
          << " for " << n << " DoFs ("
          << (all_held ? "direct up to " + std::to_string(limit) +
                           " for degree " + std::to_string(degree) :
                         std::string("a direction no fixed label holds"))
          << ")" << std::endl;
    return chosen;
  }

  const AffineConstraints<double> &
  ForwardProblem::make_step_constraints()
  {
    constraints_newton.clear();
    constraints_newton.reinit(discretization_.locally_relevant_dofs());
    if (contact != nullptr)
      contact->add_constraints(constraints_newton,
                               discretization_.base_constraints());
    constraints_newton.merge(
      discretization_.base_constraints(),
      AffineConstraints<double>::MergeConflictBehavior::left_object_wins);
    // The averaged nodal pressure assembles each owned vertex's patch,
    // which reaches DoFs of ghost cells: their contact constraints must
    // be known here as on the rank that owns them.
    if (contact != nullptr && parameters.discretization.nodal_pressure &&
        Utilities::MPI::n_mpi_processes(discretization_.communicator()) > 1)
      constraints_newton.make_consistent_in_parallel(
        discretization_.locally_owned_dofs(),
        discretization_.locally_relevant_dofs(),
        discretization_.communicator());
    constraints_newton.close();
    return constraints_newton;
  }

  void
  ForwardProblem::compute_rigid_body_modes()
  {
    // Translations and rotations about the centre of the owned nodes.
    Point<3> center;
    for (const Node &node : discretization_.owned_nodes())
      center += node.position;
    const double n =
      Utilities::MPI::sum(double(discretization_.owned_nodes().size()),
                          discretization_.communicator());
    for (unsigned int c = 0; c < 3; ++c)
      center[c] =
        Utilities::MPI::sum(center[c], discretization_.communicator()) / n;

    std::vector<std::vector<double>> modes(
      6,
      std::vector<double>(discretization_.locally_owned_dofs().n_elements(),
                          0.));
    for (const Node &node : discretization_.owned_nodes())
      {
        const Tensor<1, 3> r = node.position - center;
        for (unsigned int c = 0; c < 3; ++c)
          {
            const auto i =
              discretization_.locally_owned_dofs().index_within_set(
                node.dofs[c]);
            modes[c][i] = 1;
            for (unsigned int axis = 0; axis < 3; ++axis)
              {
                Tensor<1, 3> e;
                e[axis]            = 1;
                modes[3 + axis][i] = cross_product_3d(e, r)[c];
              }
          }
      }
    linear_solver->set_rigid_body_modes(std::move(modes));
  }


  // ------------------------------------------------------------------
  // State and queries

  const VectorType &
  ForwardProblem::displacement() const
  {
    return d_ghost;
  }

  const VectorType &
  ForwardProblem::rest_displacement() const
  {
    return w_ghost;
  }

  const LoadState &
  ForwardProblem::load() const
  {
    return current_load;
  }

  void
  ForwardProblem::set_state(const VectorType &new_d,
                            const VectorType &new_w,
                            const LoadState  &new_load)
  {
    d            = new_d;
    w            = new_w;
    d_ghost      = d;
    w_ghost      = w;
    current_load = new_load;
    pressure_prediction.forget(); // a state of its own
    nodal_volumes.forget_linearisation();
    // Not known until the new state is assembled (potential_energy()).
    total_energy = std::numeric_limits<double>::quiet_NaN();
  }

  double
  ForwardProblem::potential_energy() const
  {
    return total_energy;
  }

  const MatrixType &
  ForwardProblem::tangent_matrix() const
  {
    return tangent;
  }

  void
  ForwardProblem::update_nodal_volumes() const
  {
    BufferType d_now(d_buffer), w_now(w_buffer);
    std::copy(d.begin(), d.end(), d_now.begin());
    std::copy(w.begin(), w.end(), w_now.begin());
    d_now.update_ghost_values();
    w_now.update_ghost_values();
    nodal_volumes.update(d_now, w_now, material_table);
  }

  double
  ForwardProblem::nodal_cell_pressure(const unsigned int cell) const
  {
    return -nodal_volumes.cell(cell, material_table, 0).pressure;
  }

  const VectorType &
  ForwardProblem::raw_residual() const
  {
    return residual_raw;
  }

  const MaterialTable &
  ForwardProblem::materials() const
  {
    return material_table;
  }

  std::vector<PressurePoint>
  ForwardProblem::pressure_points() const
  {
    if (parameters.discretization.nodal_pressure)
      return nodal_volumes.pressure_points();
    return cell_pressures.last();
  }

  void
  ForwardProblem::set_pressure_offsets(std::vector<double> offsets)
  {
    if (parameters.discretization.nodal_pressure)
      nodal_volumes.set_pressure_offsets(std::move(offsets));
    else
      cell_pressures.set_offsets(std::move(offsets));
  }
} // namespace RestShape
