#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <restshape/contact.h>
#include <restshape/forward_problem.h>
#include <restshape/input_error.h>

#include <cstdio>

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

    std::string
    format(const char *fmt, double a, double b = 0, double c = 0)
    {
      char buffer[256];
      std::snprintf(buffer, sizeof(buffer), fmt, a, b, c);
      return buffer;
    }
  } // namespace

  // ------------------------------------------------------------------
  // Per-thread scratch and per-cell results of the assembly.

  struct ForwardProblem::ScratchData
  {
    ScratchData(const Mapping<3>       &mapping,
                const FiniteElement<3> &fe,
                const Quadrature<3>    &quadrature,
                const Quadrature<2>    &face_quadrature)
      : fe_values(mapping,
                  fe,
                  quadrature,
                  update_values | update_gradients | update_JxW_values)
      , fe_face_values(mapping,
                       fe,
                       face_quadrature,
                       update_values | update_normal_vectors |
                         update_JxW_values)
      , grad_d(quadrature.size())
      , grad_w(quadrature.size())
      , face_d(face_quadrature.size())
      , face_w(face_quadrature.size())
      , b(fe.n_dofs_per_cell())
      , v(fe.n_dofs_per_cell())
    {}

    ScratchData(const ScratchData &other)
      : ScratchData(other.fe_values.get_mapping(),
                    other.fe_values.get_fe(),
                    other.fe_values.get_quadrature(),
                    other.fe_face_values.get_quadrature())
    {}

    FEValues<3>               fe_values;
    FEFaceValues<3>           fe_face_values;
    std::vector<Tensor2>      grad_d, grad_w;
    std::vector<Tensor<1, 3>> face_d, face_w;
    std::vector<Tensor<1, 3>> b; // gradient w.r.t. the rest configuration
    std::vector<Tensor2>      v; // A : (e_c (x) b_j), per shape function j
  };

  struct ForwardProblem::CopyData
  {
    CopyData(const unsigned int n)
      : cell_matrix(n, n)
      , cell_rhs(n)
      , cell_external(n)
      , dofs(n)
    {}

    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;      // f_ext - f_int
    Vector<double>                       cell_external; // f_ext
    std::vector<types::global_dof_index> dofs;
    bool                                 valid = true;
    double energy                              = 0; // int W dV_rest - f_ext . d
  };

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
        mapping_         = std::make_unique<MappingFE<3>>(FE_SimplexP<3>(1));
        cell_quadrature  = QGaussSimplex<3>(degree + 1);
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
  ForwardProblem::set_contact(ContactProblem *c)
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

    linear_solver =
      std::make_unique<LinearSolver>(parameters.solver,
                                     parameters.discretization.degree);
    if (parameters.solver.linear_solver == LinearSolverType::cg_amg)
      compute_rigid_body_modes();
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
  // Assembly

  void
  ForwardProblem::local_assemble(
    const typename DoFHandler<3>::active_cell_iterator &cell,
    ScratchData                                        &scratch,
    CopyData                                           &copy,
    const Assemble                                      what) const
  {
    const unsigned int n_dofs    = fe_.n_dofs_per_cell();
    const bool         matrix    = (what == Assemble::residual_and_matrix);
    FEValues<3>       &fe_values = scratch.fe_values;
    fe_values.reinit(cell);
    cell->get_dof_indices(copy.dofs);
    copy.cell_rhs      = 0;
    copy.cell_external = 0;
    if (matrix)
      copy.cell_matrix = 0;
    copy.valid = true;

    const FEValuesExtractors::Vector u(0);
    fe_values[u].get_function_gradients(d_ghost, scratch.grad_d);
    fe_values[u].get_function_gradients(w_ghost, scratch.grad_w);

    const Label            label = cell->material_id();
    const CorotationalLaw &law   = material_table.law(label);
    // Mass from the mesh (target) geometry: rho dV_mesh, whatever the rest
    // shape; an immersing fluid (CSF) buoys it by rho_fluid dV_mesh.
    const Tensor<1, 3> body_force =
      (material_table.density(label) - parameters.loads.fluid_density) *
      current_load.acceleration;
    const Tensor2 I = unit_symmetric_tensor<3>();

    Tensor2 P;
    Tensor4 A;
    double  W   = 0;
    copy.energy = 0;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        // Rest configuration X_rest = X + w: dX_rest = G dX.
        const Tensor2 G     = I + scratch.grad_w[q];
        const double  det_G = determinant(G);
        const Tensor2 G_inv = invert(G);
        const Tensor2 F     = (I + scratch.grad_d[q]) * G_inv;
        if (!(det_G > 0) ||
            !law.evaluate(F, P, matrix ? &A : nullptr, tangent_type, &W))
          {
            copy.valid = false;
            return;
          }
        const double JxW     = fe_values.JxW(q);
        const double dV_rest = det_G * JxW;
        copy.energy += W * dV_rest;
        const Tensor2 G_inv_T = transpose(G_inv);
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const unsigned int ci = fe_.system_to_component_index(i).first;
            scratch.b[i]          = G_inv_T * fe_values.shape_grad(i, q);
            const double f_ext =
              fe_values.shape_value(i, q) * body_force[ci] * JxW;
            copy.cell_external(i) += f_ext;
            copy.cell_rhs(i) += f_ext - (P[ci] * scratch.b[i]) * dV_rest;
          }
        if (!matrix)
          continue;
        for (unsigned int j = 0; j < n_dofs; ++j)
          {
            const unsigned int cj = fe_.system_to_component_index(j).first;
            Tensor2           &v  = scratch.v[j];
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int K = 0; K < 3; ++K)
                {
                  double sum = 0;
                  for (unsigned int L = 0; L < 3; ++L)
                    sum += A[c][K][cj][L] * scratch.b[j][L];
                  v[c][K] = sum * dV_rest;
                }
          }
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const unsigned int ci = fe_.system_to_component_index(i).first;
            for (unsigned int j = 0; j <= i; ++j)
              copy.cell_matrix(i, j) += scratch.v[j][ci] * scratch.b[i];
          }
      }
    if (matrix)
      for (unsigned int i = 0; i < n_dofs; ++i)
        for (unsigned int j = i + 1; j < n_dofs; ++j)
          copy.cell_matrix(i, j) = copy.cell_matrix(j, i);

    // CSF pressure: a dead load -p n on the outer faces of the mesh.
    if (current_load.pressure != 0 && pressure_labels.count(label))
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            FEFaceValues<3> &fv = scratch.fe_face_values;
            fv.reinit(cell, f);
            for (const unsigned int q : fv.quadrature_point_indices())
              {
                const Tensor<1, 3> traction =
                  -current_load.pressure * fv.normal_vector(q);
                for (unsigned int i = 0; i < n_dofs; ++i)
                  {
                    const double f_ext =
                      fv.shape_value(i, q) *
                      traction[fe_.system_to_component_index(i).first] *
                      fv.JxW(q);
                    copy.cell_external(i) += f_ext;
                    copy.cell_rhs(i) += f_ext;
                  }
              }
          }

    // Elastic support: traction -k (d - w) on the outer faces (mesh
    // geometry), energy k/2 |d - w|^2.
    const double k = parameters.boundary.support_stiffness;
    if (k > 0 && support_labels.count(label))
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            FEFaceValues<3> &fv = scratch.fe_face_values;
            fv.reinit(cell, f);
            fv[u].get_function_values(d_ghost, scratch.face_d);
            fv[u].get_function_values(w_ghost, scratch.face_w);
            for (const unsigned int q : fv.quadrature_point_indices())
              {
                const Tensor<1, 3> u_rest =
                  scratch.face_d[q] - scratch.face_w[q];
                const double JxW = fv.JxW(q);
                copy.energy += 0.5 * k * u_rest.norm_square() * JxW;
                for (unsigned int i = 0; i < n_dofs; ++i)
                  {
                    const unsigned int ci =
                      fe_.system_to_component_index(i).first;
                    const double phi = fv.shape_value(i, q);
                    copy.cell_rhs(i) -= k * u_rest[ci] * phi * JxW;
                    if (matrix)
                      for (unsigned int j = 0; j < n_dofs; ++j)
                        if (fe_.system_to_component_index(j).first == ci)
                          copy.cell_matrix(i, j) +=
                            k * phi * fv.shape_value(j, q) * JxW;
                  }
              }
          }

    // Dead loads: their potential is -f_ext . d.
    for (unsigned int i = 0; i < n_dofs; ++i)
      copy.energy -= copy.cell_external(i) * d_ghost[copy.dofs[i]];
  }

  bool
  ForwardProblem::assemble(const Assemble what)
  {
    TimerOutput::Scope scope(timer, "Assembly");
    const bool         matrix = (what == Assemble::residual_and_matrix);
    residual_raw              = 0;
    residual_condensed        = 0;
    external_condensed        = 0;
    if (matrix)
      {
        tangent    = 0;
        rhs_newton = 0;
      }
    bool   all_valid = true;
    double energy    = 0;

    using CellFilter = FilteredIterator<DoFHandler<3>::active_cell_iterator>;
    WorkStream::run(
      CellFilter(IteratorFilters::LocallyOwnedCell(),
                 dof_handler_.begin_active()),
      CellFilter(IteratorFilters::LocallyOwnedCell(), dof_handler_.end()),
      [this, what](const CellFilter &cell, ScratchData &s, CopyData &c) {
        local_assemble(cell, s, c, what);
      },
      [this, matrix, &all_valid, &energy](const CopyData &c) {
        if (!c.valid)
          {
            all_valid = false;
            return;
          }
        energy += c.energy;
        constraints_hanging.distribute_local_to_global(c.cell_rhs,
                                                       c.dofs,
                                                       residual_raw);
        constraints_base.distribute_local_to_global(c.cell_external,
                                                    c.dofs,
                                                    external_condensed);
        constraints_newton.distribute_local_to_global(c.cell_rhs,
                                                      c.dofs,
                                                      residual_condensed);
        if (matrix)
          constraints_newton.distribute_local_to_global(
            c.cell_matrix, c.cell_rhs, c.dofs, tangent, rhs_newton);
      },
      ScratchData(*mapping_, fe_, cell_quadrature, face_quadrature_),
      CopyData(fe_.n_dofs_per_cell()));

    residual_raw.compress(VectorOperation::add);
    residual_condensed.compress(VectorOperation::add);
    external_condensed.compress(VectorOperation::add);
    if (matrix)
      {
        tangent.compress(VectorOperation::add);
        rhs_newton.compress(VectorOperation::add);
      }
    total_energy = Utilities::MPI::sum(energy, comm);
    return Utilities::MPI::min(all_valid ? 1 : 0, comm) == 1;
  }

  // ------------------------------------------------------------------
  // Newton's method with line search, inside load stepping.

  double
  ForwardProblem::linear_tolerance(const double residual,
                                   const double previous_residual,
                                   const double previous_eta,
                                   const double target) const
  {
    const double fixed = parameters.solver.linear_tolerance;
    if (!parameters.solver.inexact_newton)
      return fixed;
    // Eisenstat and Walker (1996), choice 2 with its safeguard.
    double eta = 0.1;
    if (previous_residual > 0)
      {
        const double ratio = residual / previous_residual;
        eta                = 0.9 * ratio * ratio;
        if (0.9 * previous_eta * previous_eta > 0.1)
          eta = std::max(eta, 0.9 * previous_eta * previous_eta);
        eta = std::min(eta, 0.1);
      }
    // Not tighter than the fixed tolerance; and where the Newton tolerance
    // is near, only as tight as reaching it needs.
    return std::max({eta, fixed, std::min(0.1, 0.5 * target / residual)});
  }

  bool
  ForwardProblem::newton(SolveStatistics &stats)
  {
    const double tol = parameters.solver.newton_tolerance;
    if (contact != nullptr)
      contact->begin_solve(d_ghost);

    double reference = 0;
    // Inexact Newton: the previous step's residual and linear tolerance.
    double previous_residual = 0, previous_eta = 0;
    stats.residual_history.clear();
    // adaptive: the consistent tangent, but after a step the line search
    // had to shorten, one step with the projected one.
    const TangentType chosen = parameters.discretization.tangent;
    tangent_type =
      chosen == TangentType::adaptive ? TangentType::consistent : chosen;
    for (unsigned int it = 1; it <= parameters.solver.max_newton_iterations;
         ++it)
      {
        bool set_changed = false;
        if (contact != nullptr)
          {
            set_changed =
              contact->update_active_set(d_ghost, residual_raw, it == 1);
            stats.active_set_changes += set_changed;
          }
        make_newton_constraints();

        if (!assemble(Assemble::residual_and_matrix))
          {
            stats.failure = "a cell is inverted (det F <= 0) at the start "
                            "of the Newton step";
            return false;
          }
        const double residual = residual_condensed.l2_norm();
        if (reference == 0)
          reference = external_condensed.l2_norm();
        if (reference == 0)
          reference = std::max(residual, 1e-300);
        stats.residual  = residual;
        stats.reference = reference;

        if (residual <= tol * reference &&
            (contact == nullptr || (!set_changed && contact->is_satisfied())))
          {
            if (contact == nullptr || !contact->thaw_if_adhesive(residual_raw))
              return true;
            pcout << "      active nodes pull on the obstacle: released"
                  << contact->progress_text() << std::endl;
          }

        newton_update                  = 0;
        unsigned int linear_iterations = 0;
        const double eta               = linear_tolerance(residual,
                                            previous_residual,
                                            previous_eta,
                                            tol * reference);
        previous_residual              = residual;
        previous_eta                   = eta;
        {
          TimerOutput::Scope scope(timer, "Linear solve");
          linear_iterations =
            linear_solver->solve(tangent, newton_update, rhs_newton, eta);
          stats.linear_iterations += linear_iterations;
        }
        constraints_newton.distribute(newton_update);
        ++stats.newton_iterations;

        // Backtracking. Merit: the total potential energy (Armijo), which
        // the Newton direction descends where the tangent is positive
        // definite; or, where the energy cannot resolve the change (near
        // convergence) or the tangent is indefinite, the residual norm. A
        // step that changes the contact constraints is taken whole (as far
        // as contact allows: no step carries the body through the
        // obstacle).
        const double     energy_start = total_energy;
        const double     slope        = -(residual_condensed * newton_update);
        const VectorType d_start      = d;
        const double     alpha_max =
          contact != nullptr ? contact->max_step(newton_update) : 1.;
        double       alpha           = alpha_max;
        bool         accepted        = false;
        double       trial_residual  = 0;
        unsigned int inverted_trials = 0;
        for (unsigned int ls = 0; ls < 12 && !accepted; ++ls, alpha *= 0.5)
          {
            d = d_start;
            d.add(alpha, newton_update);
            d_ghost = d;
            if (!assemble(Assemble::residual))
              {
                ++inverted_trials;
                continue;
              }
            trial_residual = residual_condensed.l2_norm();
            accepted       = (alpha == alpha_max && set_changed) ||
                       trial_residual <= (1 - 1e-4 * alpha) * residual ||
                       trial_residual <= tol * reference ||
                       (slope < 0 &&
                        total_energy <= energy_start + 1e-4 * alpha * slope);
            if (accepted)
              break;
          }
        pcout << "      Newton " << std::setw(2) << it
              << format(": |R|/|f| %9.3e -> %9.3e, step %5.3f",
                        residual / reference,
                        (accepted ? trial_residual : residual) / reference,
                        alpha)
              << (inverted_trials > 0 ? " (" + std::to_string(inverted_trials) +
                                          " shorter: a cell inverted)" :
                                        std::string())
              << (parameters.solver.linear_solver == LinearSolverType::cg_amg ?
                    ", " + linear_solver->last_method + " " +
                      std::to_string(linear_iterations) + " its" :
                    std::string())
              << (contact != nullptr ? contact->progress_text() : std::string())
              << std::endl;
        if (accepted)
          {
            stats.residual_history.push_back(trial_residual / reference);
            if (chosen == TangentType::adaptive)
              tangent_type =
                (tangent_type == TangentType::consistent && alpha < alpha_max) ?
                  TangentType::projected :
                  TangentType::consistent;
          }
        else if (chosen == TangentType::adaptive &&
                 tangent_type == TangentType::consistent)
          {
            // No step along the consistent direction helps: take the
            // projected one from the same state.
            pcout << "      no step along the consistent tangent helps: "
                     "the projected one from the same state"
                  << std::endl;
            d            = d_start;
            d_ghost      = d;
            tangent_type = TangentType::projected;
            continue;
          }
        if (!accepted)
          {
            d       = d_start;
            d_ghost = d;
            stats.failure =
              format("the line search could not reduce the residual "
                     "(|R|/|f| = %.3e)",
                     residual / reference);
            return false;
          }
      }
    stats.failure =
      "no convergence in " +
      std::to_string(parameters.solver.max_newton_iterations) +
      format(" Newton iterations (|R|/|f| = %.3e, tolerance %.1e)",
             stats.residual / stats.reference,
             tol);
    return false;
  }

  SolveStatistics
  ForwardProblem::solve(const LoadState &target_load, const VectorType &rest)
  {
    SolveStatistics  stats;
    const LoadState  start_load  = current_load;
    const VectorType w_start     = w;
    VectorType       d_converged = d;
    double           s_done = 0, ds = 1. / parameters.solver.initial_load_steps;
    unsigned int     halvings = 0;
    ContactProblem::State contact_converged;
    if (contact != nullptr)
      contact_converged = contact->state();

    while (s_done < 1)
      {
        const double s = std::min(1., s_done + ds);
        current_load.acceleration =
          start_load.acceleration +
          s * (target_load.acceleration - start_load.acceleration);
        current_load.pressure =
          start_load.pressure +
          s * (target_load.pressure - start_load.pressure);
        w = w_start;
        w.sadd(1 - s, s, rest);
        w_ghost = w;
        if (s < 1 || ds < 1)
          pcout << "    Load step to " << format("%.4f", s) << std::endl;

        if (newton(stats))
          {
            s_done      = s;
            d_converged = d;
            if (contact != nullptr)
              contact_converged = contact->state();
            ++stats.load_steps;
            ds = std::min(2 * ds, 1.);
            continue;
          }
        // Back to the last equilibrium, smaller increment.
        d       = d_converged;
        d_ghost = d;
        if (contact != nullptr)
          contact->set_state(contact_converged);
        if (++halvings > parameters.solver.max_load_step_halvings)
          {
            current_load.acceleration =
              start_load.acceleration +
              s_done * (target_load.acceleration - start_load.acceleration);
            current_load.pressure =
              start_load.pressure +
              s_done * (target_load.pressure - start_load.pressure);
            w = w_start;
            w.sadd(1 - s_done, s_done, rest);
            w_ghost = w;
            stats.failure += "; gave up after " + std::to_string(halvings - 1) +
                             " halvings of the load increment at " +
                             format("%.4f", s_done) + " of the full load";
            pcout << "    Newton failed: " << stats.failure << std::endl;
            stats.fraction = s_done;
            return stats;
          }
        pcout << "    Newton failed (" << stats.failure
              << "); halving the increment" << std::endl;
        ds /= 2;
      }
    stats.converged = true;
    stats.fraction  = 1;
    stats.failure.clear();
    return stats;
  }

  LoadState
  ForwardProblem::scene_load() const
  {
    LoadState load;
    load.acceleration = parameters.loads.gravity;
    load.pressure     = parameters.loads.pressure;
    return load;
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
  ForwardProblem::interpolate_vertex_field(
    const std::vector<Tensor<1, 3>> &values) const
  {
    VectorType  result  = zero_vector();
    const auto  linear  = scalar_element(labelled_mesh.is_simplex(), 1);
    const auto &support = fe_.base_element(0).get_unit_support_points();
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
                value += linear->shape_value(v, support[base]) *
                         values[cell->vertex_index(v)][component];
              result[dofs[i]] = value;
            }
        }
    result.compress(VectorOperation::insert);
    return result;
  }

  bool
  ForwardProblem::rest_shape_is_valid(const VectorType &rest,
                                      unsigned int     &n_bad) const
  {
    VectorType ghosted(owned_dofs, relevant_dofs, comm);
    ghosted = rest;
    FEValues<3> fe_values(*mapping_, fe_, cell_quadrature, update_gradients);
    std::vector<Tensor2>             grad_w(cell_quadrature.size());
    const FEValuesExtractors::Vector u(0);
    n_bad = 0;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_gradients(ghosted, grad_w);
          for (const Tensor2 &g : grad_w)
            if (!(determinant(Tensor2(unit_symmetric_tensor<3>()) + g) > 0))
              {
                ++n_bad;
                break;
              }
        }
    n_bad = Utilities::MPI::sum(n_bad, comm);
    return n_bad == 0;
  }

  std::pair<double, double>
  ForwardProblem::nodal_norms(const VectorType &v) const
  {
    double sum = 0, max = 0;
    for (const Node &node : owned_nodes_)
      {
        Tensor<1, 3> value;
        for (unsigned int c = 0; c < 3; ++c)
          value[c] = v[node.dofs[c]];
        sum += value.norm();
        max = std::max(max, value.norm());
      }
    const double n = Utilities::MPI::sum(double(owned_nodes_.size()), comm);
    return {Utilities::MPI::sum(sum, comm) / n, Utilities::MPI::max(max, comm)};
  }

  Vector<float>
  ForwardProblem::von_mises_stress() const
  {
    Vector<float>        result(labelled_mesh.triangulation().n_active_cells());
    FEValues<3>          fe_values(*mapping_,
                          fe_,
                          cell_quadrature,
                          update_gradients | update_JxW_values);
    std::vector<Tensor2> grad_d(cell_quadrature.size()),
      grad_w(cell_quadrature.size());
    const FEValuesExtractors::Vector u(0);
    const Tensor2                    I = unit_symmetric_tensor<3>();
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_gradients(d_ghost, grad_d);
          fe_values[u].get_function_gradients(w_ghost, grad_w);
          const CorotationalLaw &law = material_table.law(cell->material_id());
          double                 sum = 0, volume = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const Tensor2 F = (I + grad_d[q]) * invert(I + grad_w[q]);
              Tensor2       P;
              if (law.evaluate(F, P, nullptr, TangentType::warped))
                sum += von_mises(cauchy_stress(F, P)) * fe_values.JxW(q);
              volume += fe_values.JxW(q);
            }
          result[cell->active_cell_index()] = sum / volume;
        }
    return result;
  }

  Tensor<1, 3>
  ForwardProblem::support_reaction() const
  {
    // At equilibrium the raw residual f_ext - f_int vanishes at free DoFs;
    // at fixed DoFs it is minus the force the support exerts.
    Tensor<1, 3> reaction;
    for (const Node &node : owned_nodes_)
      for (unsigned int c = 0; c < 3; ++c)
        if (is_fixed(node.dofs[c]))
          reaction[c] -= residual_raw[node.dofs[c]];
    for (unsigned int c = 0; c < 3; ++c)
      reaction[c] = Utilities::MPI::sum(reaction[c], comm);
    return reaction;
  }

  Tensor<1, 3>
  ForwardProblem::elastic_support_force() const
  {
    Tensor<1, 3> force;
    const double k = parameters.boundary.support_stiffness;
    if (k > 0)
      {
        FEFaceValues<3>                  ffv(*mapping_,
                            fe_,
                            face_quadrature_,
                            update_values | update_JxW_values);
        const FEValuesExtractors::Vector u(0);
        std::vector<Tensor<1, 3>>        face_d(face_quadrature_.size()),
          face_w(face_quadrature_.size());
        for (const auto &cell : dof_handler_.active_cell_iterators())
          if (cell->is_locally_owned() &&
              support_labels.count(cell->material_id()))
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                {
                  ffv.reinit(cell, f);
                  ffv[u].get_function_values(d_ghost, face_d);
                  ffv[u].get_function_values(w_ghost, face_w);
                  for (const unsigned int q : ffv.quadrature_point_indices())
                    force -= k * (face_d[q] - face_w[q]) * ffv.JxW(q);
                }
      }
    for (unsigned int c = 0; c < 3; ++c)
      force[c] = Utilities::MPI::sum(force[c], comm);
    return force;
  }

  Tensor<1, 3>
  ForwardProblem::total_external_force(const LoadState &load) const
  {
    Tensor<1, 3>    force;
    FEValues<3>     fv(*mapping_, fe_, cell_quadrature, update_JxW_values);
    FEFaceValues<3> ffv(*mapping_,
                        fe_,
                        face_quadrature_,
                        update_normal_vectors | update_JxW_values);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          double volume = 0;
          for (const unsigned int q : fv.quadrature_point_indices())
            volume += fv.JxW(q);
          force += (material_table.density(cell->material_id()) -
                    parameters.loads.fluid_density) *
                   volume * load.acceleration;
          if (load.pressure != 0 && pressure_labels.count(cell->material_id()))
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                {
                  ffv.reinit(cell, f);
                  for (const unsigned int q : ffv.quadrature_point_indices())
                    force -= load.pressure * ffv.normal_vector(q) * ffv.JxW(q);
                }
        }
    for (unsigned int c = 0; c < 3; ++c)
      force[c] = Utilities::MPI::sum(force[c], comm);
    return force;
  }

  bool
  ForwardProblem::evaluate(const bool with_tangent)
  {
    make_newton_constraints();
    return assemble(with_tangent ? Assemble::residual_and_matrix :
                                   Assemble::residual);
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
