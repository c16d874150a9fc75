// ForwardProblem: assembly of the residual and tangent of the material
// law and the load terms (WorkStream over the locally owned cells).

#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <restshape/fem/elastic_cell.h>
#include <restshape/fem/simplex_values.h>
#include <restshape/forward/cell_pressure_modes.h>
#include <restshape/forward/forward_problem.h>

namespace RestShape
{
  using namespace dealii;

  // ------------------------------------------------------------------
  // Per-thread scratch and per-cell results of the assembly.

  struct ForwardProblem::ScratchData
  {
    ScratchData(const Mapping<3>       &mapping,
                const FiniteElement<3> &fe,
                const Quadrature<3>    &quadrature,
                const Quadrature<2>    &face_quadrature)
      : fe_values(mapping,
                  fe.base_element(0),
                  quadrature,
                  update_values | update_gradients | update_JxW_values |
                    update_quadrature_points)
      , grad_d(quadrature.size())
      , grad_w(quadrature.size())
      , F(quadrature.size())
      , G_inv(quadrature.size())
      , det_G(quadrature.size())
      , J(quadrature.size())
      , dV_rest(quadrature.size())
      , d_cell(fe)
      , w_cell(fe)
      , faces(mapping, fe, face_quadrature)
      , elastic(fe)
    {
      // Affine tetrahedra: their values without FEValues' machinery.
      const auto *mapping_fe = dynamic_cast<const MappingFE<3> *>(&mapping);
      if (fe.reference_cell() == ReferenceCells::Tetrahedron &&
          mapping_fe != nullptr && mapping_fe->get_degree() == 1)
        simplex =
          std::make_unique<SimplexValues>(fe.base_element(0), quadrature);
    }

    ScratchData(const ScratchData &other)
      : ScratchData(other.fe_values.get_mapping(),
                    other.faces.fe,
                    other.fe_values.get_quadrature(),
                    other.faces.fe_face_values.get_quadrature())
    {}

    FEValues<3>                    fe_values; // of the scalar base element
    std::vector<Tensor2>           grad_d, grad_w;
    std::vector<Tensor2>           F, G_inv;   // per point: F, (dX_rest/dX)^-1
    std::vector<double>            det_G;      // per point: dV_rest / dV
    std::vector<double>            J, dV_rest; // per point (linear pressure)
    LocalField                     d_cell, w_cell; // d and w on the cell
    FaceScratch                    faces;          // of the load terms
    ElasticCell                    elastic;        // the law's terms
    std::unique_ptr<SimplexValues> simplex;        // on affine tetrahedra
    std::vector<double>            g_local, g_all; // PressurePrediction's
    CellPressureModes              modes; // Q2-P1disc: the linear pressure
  };

  struct ForwardProblem::CopyData
  {
    CopyData(const unsigned int n)
      : cell_matrix(n, n)
      , cell_rhs(n)
      , cell_external(n)
      , cell_magnitude(n)
      , dofs(n)
      , local(n)
    {}

    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;       // f_ext - f_int
    Vector<double>                       cell_external;  // f_ext
    Vector<double>                       cell_magnitude; // |f_ext| + |f_int|
    std::vector<types::global_dof_index> dofs;
    std::vector<unsigned int>            local; // CellLocalIndices
    // The condensed pressure unknowns' rows of G (each n DoFs long) and
    // their stiffness k (records_coupling).
    std::vector<double> coupling_rows, coupling_factors;
    bool                valid      = true;
    unsigned int        cell_index = 0; // active index
    Point<3>            center;         // of an inverted cell
    types::material_id  label  = 0;
    double              energy = 0; // int W dV_rest - f_ext . d
  };

  // ------------------------------------------------------------------
  // Assembly

  struct ForwardProblem::CellVolumetric
  {
    // The pressure per mode (with one mode: U'(J_mean)) before a caller's
    // offsets, with them (the residual's), and the tangent's (Pa).
    std::array<double, CellPressureModes::n_modes> condensed{}, pressure{},
      geometric{};
    double volumetric_factor = 0; // U''(J_mean) / V (one mode)
  };

  void
  ForwardProblem::local_assemble(
    const typename DoFHandler<3>::active_cell_iterator &cell,
    ScratchData                                        &scratch,
    CopyData                                           &copy,
    const Assemble                                      what) const
  {
    const bool matrix     = (what == Assemble::residual_and_matrix);
    const bool magnitudes = (what == Assemble::residual_and_magnitudes);
    cell->get_dof_indices(copy.dofs);
    copy.cell_index = cell->active_cell_index();
    copy.valid      = true;
    cell_local_indices.get(copy.cell_index, copy.local);
    scratch.d_cell.gather_local(d_buffer, copy.local);
    scratch.w_cell.gather_local(w_buffer, copy.local);
    scratch.faces.forget();

    const Label        label = cell->material_id();
    const MaterialLaw &law   = material_table.law(label);
    // Mass from the mesh (target) geometry: rho dV_mesh, whatever the rest
    // shape; an immersing fluid (CSF) buoys it by rho_fluid dV_mesh. At the
    // centre where it does not vary over the cell (set below).
    const bool    varies = current_body_force_varies;
    Tensor<1, 3>  cell_body_force;
    const Tensor2 I = unit_symmetric_tensor<3>();

    // The law's terms at the points of @p values (of the scalar element,
    // on this cell); false at an inverted point. Mixed formulation: the
    // isochoric part of the law at each point and the volumetric energy
    // V U(J_mean) of the cell's mean dilatation J_mean = int J dV_rest / V
    // (a condensed pressure U'(J_mean) constant on the cell), its
    // stiffness U''(J_mean) / V g g^T added below; with a linear pressure
    // per cell (Q2-P1disc) the same by the cell's modes (CellPressureModes).
    const bool   mixed   = parameters.discretization.mixed;
    const bool   nodal   = parameters.discretization.nodal_pressure;
    const bool   linear  = parameters.discretization.linear_cell_pressure;
    const auto   n_modes = parameters.discretization.cell_pressure_modes();
    ElasticCell &elastic = scratch.elastic;
    elastic.reinit(magnitudes, mixed && !nodal ? n_modes : 1);
    Tensor4 A;
    double  W                = 0;
    copy.energy              = 0;
    CellPressureModes &modes = scratch.modes;
    CellVolumetric     vol; // the mixed formulation's pressures
    const bool         predicted =
      matrix && mixed && !nodal && !cell_pressures.shifted();
    const auto add_points = [&](const auto &values) {
      scratch.d_cell.gradients(values, scratch.grad_d);
      scratch.w_cell.gradients(values, scratch.grad_w);
      const unsigned int n = values.n_quadrature_points;
      double             V = 0, J_volume = 0;
      for (unsigned int q = 0; q < n; ++q)
        {
          // Rest configuration X_rest = X + w: dX_rest = G dX.
          const Tensor2 G  = I + scratch.grad_w[q];
          scratch.det_G[q] = determinant(G);
          scratch.G_inv[q] = invert(G);
          scratch.F[q]     = (I + scratch.grad_d[q]) * scratch.G_inv[q];
          if (!(scratch.det_G[q] > 0))
            return false;
          if (mixed)
            {
              const double J = determinant(scratch.F[q]);
              if (!(J > 0))
                return false;
              V += scratch.det_G[q] * values.JxW(q);
              J_volume += J * scratch.det_G[q] * values.JxW(q);
              scratch.J[q]       = J;
              scratch.dV_rest[q] = scratch.det_G[q] * values.JxW(q);
            }
        }
      if (mixed && linear)
        modes.reinit(values);
      if (mixed &&
          !cell_volumetric(scratch, copy, law, V, J_volume, matrix, vol))
        return false;
      const auto &pressure  = vol.pressure;
      const auto &geometric = vol.geometric;
      for (unsigned int q = 0; q < n; ++q)
        {
          const Tensor2     &F = scratch.F[q];
          ElasticCell::Point p;
          Tensor2            dJ;
          if (!(mixed ? law.evaluate_isochoric(
                          F, p.P, matrix ? &A : nullptr, tangent_type, &W) :
                        law.evaluate(
                          F, p.P, matrix ? &A : nullptr, tangent_type, &W)))
            return false;
          if (mixed)
            {
              const Tensor2 F_inv_T = transpose(invert(F));
              dJ                    = determinant(F) * F_inv_T;
              p.modes               = linear ? modes.at(q) : nullptr;
              p.P +=
                (linear ? modes.field_at(q, pressure.data()) : pressure[0]) *
                dJ;
              const double geometric_pressure =
                linear ? modes.field_at(q, geometric.data()) : geometric[0];
              if (matrix)
                for (unsigned int i = 0; i < 3; ++i)
                  for (unsigned int j = 0; j < 3; ++j)
                    for (unsigned int k = 0; k < 3; ++k)
                      for (unsigned int l = 0; l < 3; ++l)
                        A[i][j][k][l] +=
                          geometric_pressure *
                          (dJ[i][j] * F_inv_T[k][l] - dJ[i][l] * F_inv_T[k][j]);
              p.dJ = &dJ;
            }
          p.q       = q;
          p.G_inv_T = transpose(scratch.G_inv[q]);
          p.A       = matrix ? &A : nullptr;
          p.JxW     = values.JxW(q);
          p.dV_rest = scratch.det_G[q] * p.JxW;
          p.f_body  = varies ? load_set.body_force(*cell,
                                                  values.quadrature_point(q),
                                                  current_load) :
                               cell_body_force;
          copy.energy += W * p.dV_rest;
          elastic.add(values, p);
        }
      return true;
    };
    // As a cell of the mesh: the DoFHandler's cell is of the vector element.
    const Triangulation<3>::cell_iterator mesh_cell = cell;
    Point<3>                              center;
    if (scratch.simplex != nullptr)
      {
        scratch.simplex->reinit(mesh_cell);
        center = scratch.simplex->center();
      }
    else
      {
        scratch.fe_values.reinit(mesh_cell);
        center = cell->center();
      }
    cell_body_force  = load_set.body_force(*cell, center, current_load);
    const bool valid = scratch.simplex != nullptr ?
                         add_points(*scratch.simplex) :
                         add_points(scratch.fe_values);
    if (!valid)
      {
        copy.valid  = false;
        copy.center = cell->center();
        copy.label  = label;
        return;
      }
    elastic.vectors(copy.cell_rhs, copy.cell_external, copy.cell_magnitude);
    if (matrix && mixed && !nodal)
      {
        elastic.matrix(copy.cell_matrix);
        if (linear)
          elastic.add_volumetric_stiffness(copy.cell_matrix, modes.stiffness);
        else
          elastic.add_volumetric_stiffness(copy.cell_matrix,
                                           vol.volumetric_factor);
        if (records_coupling)
          coupling_rows(scratch,
                        coupled_fraction(law.mu, law.bulk_modulus),
                        linear ?
                          modes.stiffness :
                          FullMatrix<double>(1, 1, &vol.volumetric_factor),
                        copy);
        if (predicted)
          record_pressure_linearisation(scratch,
                                        copy.cell_index,
                                        vol.condensed.data(),
                                        linear ? &modes.stiffness(0, 0) :
                                                 &vol.volumetric_factor);
      }
    else if (matrix)
      elastic.matrix(copy.cell_matrix);

    load_set.assemble_faces({cell,
                             scratch.d_cell,
                             scratch.w_cell,
                             current_load,
                             matrix,
                             scratch.faces,
                             copy.cell_matrix,
                             copy.cell_rhs,
                             copy.cell_external,
                             copy.energy});
  }

  bool
  ForwardProblem::cell_volumetric(ScratchData       &scratch,
                                  CopyData          &copy,
                                  const MaterialLaw &law,
                                  const double       V,
                                  const double       J_volume,
                                  const bool         matrix,
                                  CellVolumetric    &vol) const
  {
    const DiscretizationParameters &d = parameters.discretization;
    if (d.nodal_pressure)
      {
        // Averaged nodal pressure: the vertices' stiffness is added
        // patch by patch (NodalVolumes::add_stiffness).
        const NodalVolumes::CellPressure c =
          nodal_volumes.cell(copy.cell_index, material_table, V);
        if (!c.valid)
          return false;
        vol.pressure[0]  = c.pressure;
        vol.geometric[0] = matrix ? c.predicted : c.pressure;
        copy.energy += c.energy;
        return true;
      }
    if (d.linear_cell_pressure)
      {
        CellPressureModes &modes = scratch.modes; // reinit by the caller
        if (!modes.condense(law, scratch.J, scratch.dV_rest))
          return false;
        copy.energy += modes.energy;
        const unsigned int n_modes = CellPressureModes::n_modes;
        for (unsigned int a = 0; a < n_modes; ++a)
          {
            const unsigned int point = copy.cell_index * n_modes + a;
            vol.condensed[a]         = modes.pressure[a];
            cell_pressures.record(point,
                                  {modes.dilatation[a],
                                   modes.pressure[a],
                                   modes.mode_stiffness[a]});
            vol.pressure[a] = cell_pressures.pressure(point, vol.condensed[a]);
          }
      }
    else
      {
        const MaterialLaw::Volumetric U = law.volumetric(J_volume / V);
        vol.volumetric_factor           = U.d2U / V;
        vol.condensed[0]                = U.dU;
        copy.energy += V * U.U;
        cell_pressures.record(copy.cell_index, {J_volume / V, U.dU, U.d2U});
        // A caller's three-field pressure (CellPressures).
        vol.pressure[0] = cell_pressures.pressure(copy.cell_index, U.dU);
      }
    // The tangent's geometric term: the pressure the three-field step
    // predicts (PressurePrediction), the residual's is U'(J_mean).
    vol.geometric = vol.pressure;
    if (matrix && !cell_pressures.shifted())
      pressure_prediction.pressure(copy.cell_index,
                                   scratch.d_cell.data(),
                                   scratch.w_cell.data(),
                                   vol.pressure.data(),
                                   vol.geometric.data());
    return true;
  }

  void
  ForwardProblem::coupling_rows(ScratchData              &scratch,
                                const double              fraction,
                                const FullMatrix<double> &stiffness,
                                CopyData                 &copy) const
  {
    // The cell's volumetric stiffness sum_ab K_ab G_a G_b^T as a sum of
    // outer products: K = Q diag(lambda) Q^T, rows sum_a Q_ab G_a.
    const unsigned int n_modes = stiffness.m();
    const unsigned int n       = copy.dofs.size();
    copy.coupling_rows.assign(n_modes * n, 0.);
    copy.coupling_factors.assign(n_modes, 0.);
    FullMatrix<double> Q(n_modes, n_modes);
    if (n_modes == 1)
      {
        Q(0, 0)                  = 1;
        copy.coupling_factors[0] = fraction * stiffness(0, 0);
      }
    else
      {
        LAPACKFullMatrix<double> K(n_modes);
        K                    = stiffness;
        const double   bound = 1 + 2 * stiffness.frobenius_norm();
        Vector<double> lambda;
        K.compute_eigenvalues_symmetric(-bound, bound, 0, lambda, Q);
        for (unsigned int b = 0; b < lambda.size(); ++b)
          copy.coupling_factors[b] = fraction * lambda[b];
        copy.coupling_factors.resize(lambda.size());
      }
    for (unsigned int a = 0; a < n_modes; ++a)
      {
        scratch.elastic.volume_gradient_in_dof_order(scratch.g_local, a);
        for (unsigned int b = 0; b < copy.coupling_factors.size(); ++b)
          for (unsigned int i = 0; i < n; ++i)
            copy.coupling_rows[b * n + i] += Q(a, b) * scratch.g_local[i];
      }
  }

  void
  ForwardProblem::record_pressure_linearisation(ScratchData       &scratch,
                                                const unsigned int cell,
                                                const double      *pressures,
                                                const double *derivatives) const
  {
    const unsigned int n_modes =
      parameters.discretization.cell_pressure_modes();
    std::vector<double> &g_all = scratch.g_all;
    g_all.clear();
    for (unsigned int a = 0; a < n_modes; ++a)
      {
        scratch.elastic.volume_gradient_in_dof_order(scratch.g_local, a);
        g_all.insert(g_all.end(),
                     scratch.g_local.begin(),
                     scratch.g_local.end());
      }
    pressure_prediction.record(cell,
                               scratch.d_cell.data(),
                               scratch.w_cell.data(),
                               pressures,
                               derivatives,
                               g_all);
  }

  ForwardProblem::ScratchData &
  ForwardProblem::scratch_of_this_thread()
  {
    std::shared_ptr<ScratchData> &scratch = thread_scratch.get();
    if (!scratch)
      scratch =
        std::make_shared<ScratchData>(discretization_.mapping(),
                                      discretization_.fe(),
                                      discretization_.quadrature(),
                                      discretization_.face_quadrature());
    return *scratch;
  }

  bool
  ForwardProblem::assemble(const Assemble what)
  {
    TimerOutput::Scope scope(timer, "Assembly");
    const bool         matrix = (what == Assemble::residual_and_matrix);
    // The cell vectors go into deal.II's distributed vectors, whose element
    // access is an index shift: Trilinos's costs a map look-up and state
    // checks per entry, which made the vector additions as costly as the
    // matrix ones (profile of the brain forward solve).
    for (const auto &[v, buffer] :
         {std::pair(&d, &d_buffer), std::pair(&w, &w_buffer)})
      {
        std::copy(v->begin(), v->end(), buffer->begin());
        buffer->update_ghost_values();
      }
    raw_buffer       = 0;
    condensed_buffer = 0;
    external_buffer  = 0;
    if (what == Assemble::residual_and_magnitudes)
      magnitude_buffer = 0;
    if (matrix)
      {
        tangent    = 0;
        rhs_buffer = 0;
        pressure_coupling.clear();
        if (splits_tangent)
          split_tangent.clear();
      }
    for (const auto &[lookup, constraints] :
         {std::pair(&lookup_hanging, &discretization_.hanging_constraints()),
          std::pair(&lookup_base, &discretization_.base_constraints()),
          std::pair(&lookup_newton,
                    static_cast<const AffineConstraints<double> *>(
                      &constraints_newton))})
      lookup->reinit(*constraints, *raw_buffer.get_partitioner());
    if (parameters.discretization.nodal_pressure)
      nodal_volumes.update(d_buffer, w_buffer, material_table);
    current_body_force_varies = load_set.body_force_varies(current_load);
    bool          all_valid   = true;
    double        energy      = 0;
    InvertedCells inverted;

    using CellFilter = FilteredIterator<DoFHandler<3>::active_cell_iterator>;
    struct NoScratch // each thread keeps its own (thread_scratch)
    {};
    WorkStream::run(
      CellFilter(IteratorFilters::LocallyOwnedCell(),
                 discretization_.dof_handler().begin_active()),
      CellFilter(IteratorFilters::LocallyOwnedCell(),
                 discretization_.dof_handler().end()),
      [this, what](const CellFilter &cell, NoScratch &, CopyData &c) {
        local_assemble(cell, scratch_of_this_thread(), c, what);
      },
      [this, what, matrix, &all_valid, &energy, &inverted](const CopyData &c) {
        if (!c.valid)
          {
            if (all_valid)
              {
                inverted.center = c.center;
                inverted.label  = c.label;
              }
            ++inverted.count;
            all_valid = false;
            return;
          }
        energy += c.energy;
        lookup_hanging.distribute(c.cell_rhs, c.dofs, c.local, raw_buffer);
        lookup_base.distribute(c.cell_external,
                               c.dofs,
                               c.local,
                               external_buffer);
        lookup_newton.distribute(c.cell_rhs, c.dofs, c.local, condensed_buffer);
        if (what == Assemble::residual_and_magnitudes)
          lookup_newton.distribute(c.cell_magnitude,
                                   c.dofs,
                                   c.local,
                                   magnitude_buffer);
        if (matrix && records_coupling)
          for (unsigned int r = 0; r < c.coupling_factors.size(); ++r)
            pressure_coupling.add(c.dofs,
                                  &c.coupling_rows[r * c.dofs.size()],
                                  c.coupling_factors[r],
                                  constraints_newton);
        if (matrix)
          scatter.add(c.cell_index,
                      lookup_newton,
                      c.local,
                      c.cell_matrix,
                      c.cell_rhs,
                      c.dofs,
                      splits_tangent ? split_tangent.narrow() : tangent,
                      rhs_buffer);
      },
      NoScratch(),
      CopyData(discretization_.fe().n_dofs_per_cell()),
      2 * MultithreadInfo::n_threads(),
      64);

    // The vertices' volumetric stiffness (averaged nodal pressure), where
    // every cell is valid on every rank (add_stiffness is not collective,
    // but the matrix's compress below is).
    const bool valid_everywhere =
      Utilities::MPI::min(all_valid ? 1 : 0, discretization_.communicator()) ==
      1;
    if (matrix && valid_everywhere && parameters.discretization.nodal_pressure)
      {
        nodal_volumes.add_stiffness(d_buffer,
                                    material_table,
                                    constraints_newton,
                                    tangent,
                                    rhs_buffer,
                                    records_coupling ? &pressure_coupling :
                                                       nullptr,
                                    splits_tangent ? &split_tangent : nullptr);
        nodal_volumes.record_linearisation(d_buffer);
      }
    const auto finish = [](BufferType &buffer, VectorType &v) {
      buffer.compress(VectorOperation::add);
      std::copy(buffer.begin(), buffer.end(), v.begin());
    };
    finish(raw_buffer, residual_raw);
    finish(condensed_buffer, residual_condensed);
    finish(external_buffer, external_condensed);
    if (matrix)
      {
        tangent.compress(VectorOperation::add);
        if (splits_tangent)
          split_tangent.finish(tangent); // tangent += the cells' matrices
        finish(rhs_buffer, rhs_newton);
        if (records_coupling)
          pressure_coupling.finish(discretization_.locally_owned_dofs(),
                                   discretization_.communicator());
      }
    total_energy = Utilities::MPI::sum(energy, discretization_.communicator());
    if (valid_everywhere)
      return true;
    // One inverted cell to name: that of the lowest rank that has one.
    const std::vector<double> mine = {double(inverted.count),
                                      inverted.center[0],
                                      inverted.center[1],
                                      inverted.center[2],
                                      double(inverted.label)};
    inverted_cells.count           = 0;
    for (const auto &r :
         Utilities::MPI::all_gather(discretization_.communicator(), mine))
      {
        if (r[0] > 0 && inverted_cells.count == 0)
          {
            inverted_cells.center = Point<3>(r[1], r[2], r[3]);
            inverted_cells.label  = types::material_id(r[4]);
          }
        inverted_cells.count += static_cast<unsigned int>(r[0]);
      }
    return false;
  }

  bool
  ForwardProblem::evaluate(const bool tangent)
  {
    make_step_constraints();
    return assemble(tangent ? Assemble::residual_and_matrix :
                              Assemble::residual);
  }
} // namespace RestShape
