// What is derived from a ForwardProblem's state: distances to a target,
// the image's mass ratios, stresses, reactions and forces.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <restshape/forward/cell_pressure_modes.h>
#include <restshape/forward/forward_results.h>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Call @p f(cell, fe_values, grad_d, grad_w) for every locally owned
    /// cell: the FEValues (with @p flags and gradients) on it and the
    /// gradients of the displacement and the rest shift at its points.
    template <typename Function>
    void
    for_each_owned_cell_gradients(const ForwardProblem &forward,
                                  const UpdateFlags     flags,
                                  Function            &&f)
    {
      FEValues<3>          fe_values(forward.discretization().mapping(),
                            forward.discretization().fe(),
                            forward.discretization().quadrature(),
                            flags | update_gradients);
      const unsigned int   n_q = forward.discretization().quadrature().size();
      std::vector<Tensor2> grad_d(n_q), grad_w(n_q);
      const FEValuesExtractors::Vector u(0);
      for (const auto &cell :
           forward.discretization().dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[u].get_function_gradients(forward.displacement(), grad_d);
            fe_values[u].get_function_gradients(forward.rest_displacement(),
                                                grad_w);
            f(cell, fe_values, grad_d, grad_w);
          }
    }
  } // namespace

  std::pair<double, double>
  distance_to(const ForwardProblem        &forward,
              const std::vector<Point<3>> &targets)
  {
    std::vector<bool> seen(targets.size(), false);
    double            sum = 0, max = 0, n = 0;
    for (const auto &cell :
         forward.discretization().dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int i = cell->vertex_index(v);
            if (i >= targets.size() || seen[i] ||
                !forward.discretization().locally_owned_dofs().is_element(
                  cell->vertex_dof_index(v, 0)))
              continue;
            seen[i]    = true;
            Point<3> x = cell->vertex(v);
            for (unsigned int c = 0; c < 3; ++c)
              x[c] += forward.displacement()[cell->vertex_dof_index(v, c)];
            const double e = x.distance(targets[i]);
            sum += e;
            max = std::max(max, e);
            n += 1;
          }
    n = Utilities::MPI::sum(n, forward.discretization().communicator());
    return {n > 0 ?
              Utilities::MPI::sum(sum,
                                  forward.discretization().communicator()) /
                n :
              0.,
            Utilities::MPI::max(max, forward.discretization().communicator())};
  }

  std::vector<double>
  image_mass_ratios(const ForwardProblem &forward)
  {
    std::vector<double> ratios(
      forward.discretization().mesh().triangulation().n_global_active_cells(),
      0.);
    FEValues<3>          fe_values(forward.discretization().mapping(),
                          forward.discretization().fe(),
                          forward.discretization().quadrature(),
                          update_gradients | update_JxW_values);
    std::vector<Tensor2> grad_w(forward.discretization().quadrature().size());
    const FEValuesExtractors::Vector u(0);
    for (const auto &cell :
         forward.discretization().dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_gradients(forward.rest_displacement(),
                                              grad_w);
          double mesh_volume = 0, rest_volume = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              mesh_volume += fe_values.JxW(q);
              rest_volume +=
                determinant(Tensor2(unit_symmetric_tensor<3>()) + grad_w[q]) *
                fe_values.JxW(q);
            }
          ratios[forward.discretization().mesh().cell_index(*cell)] =
            forward.discretization().mesh().mass_ratio(*cell) * mesh_volume /
            rest_volume;
        }
    Utilities::MPI::sum(ratios,
                        forward.discretization().communicator(),
                        ratios);
    return ratios;
  }

  Vector<float>
  von_mises_stress(const ForwardProblem &forward)
  {
    Vector<float> result(
      forward.discretization().mesh().triangulation().n_active_cells());
    const Tensor2 I     = unit_symmetric_tensor<3>();
    const bool    mixed = forward.scene_parameters().discretization.mixed;
    for_each_owned_cell_gradients(
      forward,
      update_JxW_values,
      [&](const auto &cell,
          const auto &fe_values,
          const auto &grad_d,
          const auto &grad_w) {
        const MaterialLaw &law = forward.materials().law(cell->material_id());
        double             sum = 0, volume = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Tensor2 F = (I + grad_d[q]) * invert(I + grad_w[q]);
            Tensor2       P;
            // The mixed pressure is isotropic: no part of von Mises.
            if (mixed ?
                  law.evaluate_isochoric(F, P, nullptr, TangentType::warped) :
                  law.evaluate(F, P, nullptr, TangentType::warped))
              sum += von_mises(cauchy_stress(F, P)) * fe_values.JxW(q);
            volume += fe_values.JxW(q);
          }
        result[cell->active_cell_index()] = sum / volume;
      });
    return result;
  }

  VolumeFields
  volume_fields(const ForwardProblem &forward)
  {
    const unsigned int n =
      forward.discretization().mesh().triangulation().n_active_cells();
    VolumeFields  result{Vector<float>(n), Vector<float>(n)};
    const Tensor2 I     = unit_symmetric_tensor<3>();
    const bool    mixed = forward.scene_parameters().discretization.mixed;
    const bool nodal = forward.scene_parameters().discretization.nodal_pressure;
    const bool linear =
      forward.scene_parameters().discretization.linear_cell_pressure;
    if (nodal)
      forward.update_nodal_volumes();
    CellPressureModes   modes; // Q2-P1disc: the cell's mean pressure
    std::vector<double> J, dV_rest;
    for_each_owned_cell_gradients(
      forward,
      update_JxW_values | update_quadrature_points,
      [&](const auto &cell,
          const auto &fe_values,
          const auto &grad_d,
          const auto &grad_w) {
        const MaterialLaw &law  = forward.materials().law(cell->material_id());
        double             rest = 0, current = 0, pressure = 0;
        J.clear();
        dV_rest.clear();
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Tensor2 G  = I + grad_w[q];
            const Tensor2 F  = (I + grad_d[q]) * invert(G);
            const double  dV = determinant(G) * fe_values.JxW(q);
            Tensor2       P;
            rest += dV;
            current += determinant(F) * dV;
            J.push_back(determinant(F));
            dV_rest.push_back(dV);
            if (!mixed && law.evaluate(F, P, nullptr, TangentType::warped))
              pressure -= trace(cauchy_stress(F, P)) / 3 * dV;
          }
        const unsigned int i   = cell->active_cell_index();
        result.volume_ratio[i] = current / rest;
        // (A state the assembly accepted has J~ > 0 at every point.)
        bool projected = false;
        if (linear)
          {
            modes.reinit(fe_values);
            projected = modes.condense(law, J, dV_rest);
          }
        if (projected)
          result.pressure[i] = -modes.mean(modes.pressure.data());
        else
          result.pressure[i] = nodal ? forward.nodal_cell_pressure(i) :
                               mixed ? -law.volumetric(current / rest).dU :
                                       pressure / rest;
      });
    return result;
  }

  Compression
  most_compressed_cell(const ForwardProblem &forward)
  {
    const Tensor2 I = unit_symmetric_tensor<3>();
    Compression   mine;
    for_each_owned_cell_gradients(
      forward,
      update_default,
      [&](const auto &cell,
          const auto &fe_values,
          const auto &grad_d,
          const auto &grad_w) {
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double det_F =
              determinant(I + grad_d[q]) / determinant(I + grad_w[q]);
            if (det_F < mine.det_F)
              {
                mine.det_F = det_F;
                mine.where =
                  cell_location_text(cell->material_id(), cell->center());
              }
          }
      });
    Compression result;
    for (const auto &[det_F, where] :
         Utilities::MPI::all_gather(forward.discretization().communicator(),
                                    std::make_pair(mine.det_F, mine.where)))
      if (det_F < result.det_F)
        result = {det_F, where};
    return result;
  }

  Tensor<1, 3>
  support_reaction(const ForwardProblem &forward)
  {
    // At equilibrium the raw residual f_ext - f_int vanishes at free DoFs;
    // at fixed DoFs it is minus the force the support exerts.
    Tensor<1, 3> reaction;
    for (const Node &node : forward.discretization().owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        if (forward.discretization().is_fixed(node.dofs[c]))
          reaction[c] -= forward.raw_residual()[node.dofs[c]];
    for (unsigned int c = 0; c < 3; ++c)
      reaction[c] =
        Utilities::MPI::sum(reaction[c],
                            forward.discretization().communicator());
    return reaction;
  }

  Tensor<1, 3>
  elastic_support_force(const ForwardProblem &forward)
  {
    return forward.loads().resultant(forward.load(),
                                     forward.displacement(),
                                     forward.rest_displacement(),
                                     true,
                                     forward.discretization().communicator());
  }

  Tensor<1, 3>
  total_external_force(const ForwardProblem &forward, const LoadState &load)
  {
    Tensor<1, 3> force;
    FEValues<3>  fv(forward.discretization().mapping(),
                   forward.discretization().fe(),
                   forward.discretization().quadrature(),
                   update_JxW_values | update_quadrature_points);
    for (const auto &cell :
         forward.discretization().dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          for (const unsigned int q : fv.quadrature_point_indices())
            force +=
              forward.loads().body_force(*cell, fv.quadrature_point(q), load) *
              fv.JxW(q);
        }
    for (unsigned int c = 0; c < 3; ++c)
      force[c] =
        Utilities::MPI::sum(force[c], forward.discretization().communicator());
    return force + surface_force(forward, load);
  }

  Tensor<1, 3>
  surface_force(const ForwardProblem &forward, const LoadState &load)
  {
    return forward.loads().resultant(load,
                                     forward.displacement(),
                                     forward.rest_displacement(),
                                     false,
                                     forward.discretization().communicator());
  }
  bool
  rest_shape_is_valid(const Discretization &discretization,
                      const VectorType     &rest,
                      unsigned int         &n_bad,
                      std::string          *where)
  {
    const VectorType ghosted = discretization.ghosted_copy(rest);
    FEValues<3>      fe_values(discretization.mapping(),
                          discretization.fe(),
                          discretization.quadrature(),
                          update_gradients);
    n_bad = 0;
    std::string first;
    for (const auto &cell :
         discretization.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          if (!(discretization.smallest_jacobian(fe_values, ghosted) > 0) &&
              n_bad++ == 0)
            first = cell_location_text(cell->material_id(), cell->center());
        }
    n_bad = Utilities::MPI::sum(n_bad, discretization.communicator());
    if (where != nullptr && n_bad > 0)
      for (const std::string &text :
           Utilities::MPI::all_gather(discretization.communicator(), first))
        if (!text.empty())
          {
            *where = text;
            break;
          }
    return n_bad == 0;
  }
} // namespace RestShape
