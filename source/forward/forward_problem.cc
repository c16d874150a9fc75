// ForwardProblem: set-up (DoFs, constraints, rigid-body modes) and state.
// Assembly is in forward_problem_assembly.cc, Newton's method and load
// stepping in forward_problem_newton.cc, the results (norms, stresses,
// forces, energy) in forward_problem_results.cc.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <restshape/base/input_error.h>
#include <restshape/forward/forward_problem.h>

#include <cmath>
#include <limits>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    std::unique_ptr<FiniteElement<3>>
    scalar_element(const bool simplex, const unsigned int degree)
    {
      if (simplex)
        return std::make_unique<FE_SimplexP<3>>(degree);
      return std::make_unique<FE_Q<3>>(degree);
    }
  } // namespace

  // ------------------------------------------------------------------

  ForwardProblem::ForwardProblem(const Parameters    &parameters,
                                 LabelledMesh        &mesh,
                                 const MaterialTable &materials,
                                 TimerOutput         &timer,
                                 ConditionalOStream  &pcout)
    : parameters(parameters)
    , labelled_mesh(mesh)
    , material_table(materials)
    , timer(timer)
    , pcout(pcout)
    , comm(mesh.triangulation().get_communicator())
    , fe_(*scalar_element(mesh.is_simplex(), parameters.discretization.degree),
          3)
    , dof_handler_(mesh.triangulation())
    , tangent_type(parameters.discretization.tangent == TangentType::adaptive ?
                     TangentType::consistent :
                     parameters.discretization.tangent)
  {
    const unsigned int degree = parameters.discretization.degree;
    if (mesh.is_simplex())
      {
        mapping_ = std::make_unique<MappingFE<3>>(FE_SimplexP<3>(1));
        // On the (affine) P1 tetrahedron the gradients, hence F, P and the
        // tangent, are constant and the body force is linear: the centroid
        // rule integrates everything exactly, at a quarter of the cost of
        // the 4-point rule.
        cell_quadrature  = QGaussSimplex<3>(degree == 1 ? 1 : degree + 1);
        face_quadrature_ = QGaussSimplex<2>(degree + 1);
      }
    else
      {
        mapping_         = std::make_unique<MappingQ<3>>(1);
        cell_quadrature  = QGauss<3>(degree + 1);
        face_quadrature_ = QGauss<2>(degree + 1);
      }
  }

  ForwardProblem::~ForwardProblem()
  {
    dof_handler_.clear();
  }

  void
  ForwardProblem::set_contact(ActiveSetConstraints *c)
  {
    contact = c;
  }

  void
  ForwardProblem::setup()
  {
    TimerOutput::Scope scope(timer, "Setup");
    // The solver's factorisation refers to the old matrix: release it first.
    linear_solver.reset();
    dof_handler_.reinit(labelled_mesh.triangulation());
    dof_handler_.distribute_dofs(fe_);
    owned_dofs = dof_handler_.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler_, relevant_dofs);

    setup_nodes();
    setup_constraints();

    DynamicSparsityPattern dsp(relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler_, dsp, constraints_base, true);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               owned_dofs,
                                               comm,
                                               relevant_dofs);
    tangent.reinit(owned_dofs, owned_dofs, dsp, comm);

    for (VectorType *v : {&rhs_newton,
                          &residual_raw,
                          &residual_condensed,
                          &external_condensed,
                          &newton_update,
                          &d,
                          &w})
      v->reinit(owned_dofs, comm);
    d_ghost.reinit(owned_dofs, relevant_dofs, comm);
    w_ghost.reinit(owned_dofs, relevant_dofs, comm);
    // The buffers copy into the Trilinos vectors entry by entry: both store
    // the owned entries in the order of their (contiguous) global indices.
    AssertThrow(owned_dofs.is_contiguous(),
                ExcMessage("the locally owned DoFs are not contiguous"));
    for (BufferType *b : {&d_buffer,
                          &w_buffer,
                          &raw_buffer,
                          &condensed_buffer,
                          &external_buffer,
                          &rhs_buffer,
                          &magnitude_buffer})
      b->reinit(owned_dofs, relevant_dofs, comm);
    current_load = LoadState();

    // Pressure and elastic-support faces: the given labels, or every label
    // not fully fixed.
    const auto labels_or_unfixed = [this](const std::set<Label> &given) {
      std::set<Label> result = given;
      if (result.empty())
        for (const Label label : labelled_mesh.labels())
          {
            bool fully_fixed = false;
            for (const auto &f : parameters.boundary.fixed_labels)
              if (f.label == label && f.components[0] && f.components[1] &&
                  f.components[2])
                fully_fixed = true;
            if (!fully_fixed)
              result.insert(label);
          }
      return result;
    };
    pressure_labels = labels_or_unfixed(parameters.loads.pressure_labels);
    support_labels  = labels_or_unfixed(parameters.boundary.support_labels);
    setup_surface_load();

    SolverParameters solver = parameters.solver;
    solver.linear_solver    = resolve_linear_solver();
    linear_solver_type      = solver.linear_solver;
    linear_solver =
      std::make_unique<LinearSolver>(solver,
                                     parameters.discretization.degree,
                                     &timer);
    linear_solver->set_symmetric(symmetric_tangent);
    if (linear_solver_type == LinearSolverType::cg_amg)
      compute_rigid_body_modes();
  }

  LinearSolverType
  ForwardProblem::resolve_linear_solver() const
  {
    if (parameters.solver.linear_solver != LinearSolverType::automatic)
      return parameters.solver.linear_solver;
    const types::global_dof_index n = dof_handler_.n_dofs();
    // A direction that no fixed label holds leaves the tangent singular
    // until contact or the support acts: CG cannot solve that, the direct
    // solver can.
    const std::array<bool, 3> held     = fixed_components();
    const bool                all_held = held[0] && held[1] && held[2];
    const LinearSolverType    chosen   = n <= auto_direct_dofs || !all_held ?
                                           LinearSolverType::direct :
                                           LinearSolverType::cg_amg;
    pcout << "Linear solver: auto chose "
          << (chosen == LinearSolverType::direct ? "direct" : "cg-amg")
          << " for " << n << " DoFs ("
          << (all_held ? "direct up to " + std::to_string(auto_direct_dofs) :
                         std::string("a direction no fixed label holds"))
          << ")" << std::endl;
    return chosen;
  }

  bool
  ForwardProblem::is_held(const types::global_dof_index dof) const
  {
    // A hanging DoF on the edge of a fixed cell follows that edge's DoFs.
    if (is_fixed(dof))
      return true;
    if (!constraints_hanging.is_constrained(dof))
      return false;
    const auto *entries = constraints_hanging.get_constraint_entries(dof);
    return entries != nullptr && !entries->empty() &&
           std::all_of(entries->begin(), entries->end(), [this](const auto &e) {
             return is_fixed(e.first);
           });
  }

  void
  ForwardProblem::setup_nodes()
  {
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(*mapping_,
                                         dof_handler_,
                                         support_points);
    owned_nodes_.clear();
    relevant_nodes_.clear();
    std::set<types::global_dof_index>    seen;
    std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < fe_.n_dofs_per_cell(); ++i)
          {
            const auto [component, base] = fe_.system_to_component_index(i);
            if (component != 0 || !seen.insert(dofs[i]).second)
              continue;
            Node node;
            for (unsigned int c = 0; c < 3; ++c)
              node.dofs[c] = dofs[fe_.component_to_system_index(c, base)];
            node.position = support_points.at(dofs[i]);
            relevant_nodes_.push_back(node);
            if (owned_dofs.is_element(dofs[i]))
              owned_nodes_.push_back(node);
          }
      }
  }

  void
  ForwardProblem::setup_constraints()
  {
    constraints_hanging.clear();
    constraints_hanging.reinit(relevant_dofs);
    // deal.II 9.4 has no hanging nodes on simplices (and crashes when asked
    // for them); tetrahedral meshes are only refined globally.
    if (!labelled_mesh.is_simplex())
      DoFTools::make_hanging_node_constraints(dof_handler_,
                                              constraints_hanging);
    constraints_hanging.close();

    constraints_base.clear();
    constraints_base.reinit(relevant_dofs);
    constraints_base.merge(constraints_hanging);
    fixed_dof.assign(relevant_dofs.n_elements(), false);
    std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        for (const auto &fixed : parameters.boundary.fixed_labels)
          if (fixed.label == cell->material_id())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (fixed.components[fe_.system_to_component_index(i).first])
                  {
                    fixed_dof[relevant_dofs.index_within_set(dofs[i])] = true;
                    if (!constraints_base.is_constrained(dofs[i]))
                      constraints_base.add_line(dofs[i]);
                  }
            }
      }
    constraints_base.close();
    make_newton_constraints();
  }

  void
  ForwardProblem::make_newton_constraints()
  {
    constraints_newton.clear();
    constraints_newton.reinit(relevant_dofs);
    if (contact != nullptr)
      contact->add_constraints(constraints_newton, constraints_base);
    constraints_newton.merge(
      constraints_base,
      AffineConstraints<double>::MergeConflictBehavior::left_object_wins);
    constraints_newton.close();
  }

  void
  ForwardProblem::compute_rigid_body_modes()
  {
    // Translations and rotations about the centre of the owned nodes.
    Point<3> center;
    for (const Node &node : owned_nodes_)
      center += node.position;
    const double n = Utilities::MPI::sum(double(owned_nodes_.size()), comm);
    for (unsigned int c = 0; c < 3; ++c)
      center[c] = Utilities::MPI::sum(center[c], comm) / n;

    std::vector<std::vector<double>> modes(
      6, std::vector<double>(owned_dofs.n_elements(), 0.));
    for (const Node &node : owned_nodes_)
      {
        const Tensor<1, 3> r = node.position - center;
        for (unsigned int c = 0; c < 3; ++c)
          {
            const auto i = owned_dofs.index_within_set(node.dofs[c]);
            modes[c][i]  = 1;
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
    // Not known until the new state is assembled (potential_energy()).
    total_energy = std::numeric_limits<double>::quiet_NaN();
  }

  VectorType
  ForwardProblem::zero_vector() const
  {
    VectorType v(owned_dofs, comm);
    return v;
  }

  VectorType
  ForwardProblem::owned_copy(const VectorType &v) const
  {
    VectorType copy(owned_dofs, comm);
    copy = v;
    return copy;
  }

  VectorType
  ForwardProblem::ghosted_copy(const VectorType &v) const
  {
    VectorType copy(owned_dofs, relevant_dofs, comm);
    copy = v;
    return copy;
  }

  std::vector<std::vector<double>>
  ForwardProblem::vertex_weights() const
  {
    const auto linear = scalar_element(labelled_mesh.is_simplex(), 1);
    std::vector<std::vector<double>> weights;
    for (const Point<3> &p : fe_.base_element(0).get_unit_support_points())
      {
        weights.emplace_back(linear->n_dofs_per_cell());
        for (unsigned int v = 0; v < weights.back().size(); ++v)
          weights.back()[v] = linear->shape_value(v, p);
      }
    return weights;
  }

  double
  ForwardProblem::smallest_jacobian(const FEValues<3> &fe_values,
                                    const VectorType  &w)
  {
    std::vector<Tensor2> grad_w(fe_values.n_quadrature_points);
    fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(w, grad_w);
    double least = std::numeric_limits<double>::max();
    for (const Tensor2 &g : grad_w)
      {
        const double d = determinant(Tensor2(unit_symmetric_tensor<3>()) + g);
        if (std::isnan(d))
          return d;
        least = std::min(least, d);
      }
    return least;
  }

  VectorType
  ForwardProblem::interpolate_vertex_field(
    const std::vector<Tensor<1, 3>> &values) const
  {
    VectorType                           result  = zero_vector();
    const auto                           weights = vertex_weights();
    std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              if (!owned_dofs.is_element(dofs[i]))
                continue;
              const auto [component, base] = fe_.system_to_component_index(i);
              double value                 = 0;
              for (unsigned int v = 0; v < cell->n_vertices(); ++v)
                value +=
                  weights[base][v] * values[cell->vertex_index(v)][component];
              result[dofs[i]] = value;
            }
        }
    result.compress(VectorOperation::insert);
    return result;
  }

  bool
  ForwardProblem::rest_shape_is_valid(const VectorType &rest,
                                      unsigned int     &n_bad,
                                      std::string      *where) const
  {
    const VectorType ghosted = ghosted_copy(rest);
    FEValues<3> fe_values(*mapping_, fe_, cell_quadrature, update_gradients);
    n_bad = 0;
    std::string first;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          if (!(smallest_jacobian(fe_values, ghosted) > 0) && n_bad++ == 0)
            first = cell_location_text(cell->material_id(), cell->center());
        }
    n_bad = Utilities::MPI::sum(n_bad, comm);
    if (where != nullptr && n_bad > 0)
      for (const std::string &text : Utilities::MPI::all_gather(comm, first))
        if (!text.empty())
          {
            *where = text;
            break;
          }
    return n_bad == 0;
  }

  const SurfaceLoad &
  ForwardProblem::surface_load() const
  {
    return *surface_load_;
  }

  bool
  ForwardProblem::tangent_is_symmetric() const
  {
    return symmetric_tangent;
  }

  const MatrixType &
  ForwardProblem::tangent_matrix() const
  {
    return tangent;
  }

  const VectorType &
  ForwardProblem::raw_residual() const
  {
    return residual_raw;
  }

  const DoFHandler<3> &
  ForwardProblem::dof_handler() const
  {
    return dof_handler_;
  }

  const Mapping<3> &
  ForwardProblem::mapping() const
  {
    return *mapping_;
  }

  const FESystem<3> &
  ForwardProblem::fe() const
  {
    return fe_;
  }

  const Quadrature<2> &
  ForwardProblem::face_quadrature() const
  {
    return face_quadrature_;
  }

  const AffineConstraints<double> &
  ForwardProblem::base_constraints() const
  {
    return constraints_base;
  }

  const IndexSet &
  ForwardProblem::locally_owned_dofs() const
  {
    return owned_dofs;
  }

  const IndexSet &
  ForwardProblem::locally_relevant_dofs() const
  {
    return relevant_dofs;
  }

  const std::vector<Node> &
  ForwardProblem::owned_nodes() const
  {
    return owned_nodes_;
  }

  const std::vector<Node> &
  ForwardProblem::relevant_nodes() const
  {
    return relevant_nodes_;
  }

  bool
  ForwardProblem::is_fixed(const types::global_dof_index dof) const
  {
    return fixed_dof[relevant_dofs.index_within_set(dof)];
  }

  std::array<bool, 3>
  ForwardProblem::fixed_components() const
  {
    std::array<double, 3> n_fixed{{0, 0, 0}};
    for (const Node &node : owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        n_fixed[c] += is_fixed(node.dofs[c]);
    const MPI_Comm      comm = dof_handler_.get_communicator();
    std::array<bool, 3> result;
    for (unsigned int c = 0; c < 3; ++c)
      result[c] = Utilities::MPI::sum(n_fixed[c], comm) > 0;
    return result;
  }

  const LabelledMesh &
  ForwardProblem::mesh() const
  {
    return labelled_mesh;
  }

  const MaterialTable &
  ForwardProblem::materials() const
  {
    return material_table;
  }
} // namespace RestShape
