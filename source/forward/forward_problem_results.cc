// ForwardProblem's results at the current state: nodal norms, distances
// to a target, stresses, reactions, forces and the potential energy.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <restshape/forward/forward_problem.h>

namespace RestShape
{
  using namespace dealii;

  std::pair<double, double>
  ForwardProblem::nodal_norms(const VectorType &v) const
  {
    const NodalNorms all = nodal_norms_above(v, -1.);
    return {all.mean, all.max};
  }

  ForwardProblem::NodalNorms
  ForwardProblem::nodal_norms_above(const VectorType &v,
                                    const double      threshold) const
  {
    double       sum = 0, max = 0;
    unsigned int n = 0;
    for (const Node &node : owned_nodes_)
      {
        Tensor<1, 3> value;
        for (unsigned int c = 0; c < 3; ++c)
          value[c] = v[node.dofs[c]];
        if (value.norm() > threshold)
          {
            ++n;
            sum += value.norm();
          }
        max = std::max(max, value.norm());
      }
    NodalNorms result;
    result.n    = Utilities::MPI::sum(n, comm);
    result.mean = Utilities::MPI::sum(sum, comm) / std::max(1u, result.n);
    result.max  = Utilities::MPI::max(max, comm);
    return result;
  }

  std::pair<double, double>
  ForwardProblem::distance_to(const std::vector<Point<3>> &targets) const
  {
    std::vector<bool> seen(targets.size(), false);
    double            sum = 0, max = 0, n = 0;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int i = cell->vertex_index(v);
            if (i >= targets.size() || seen[i] ||
                !owned_dofs.is_element(cell->vertex_dof_index(v, 0)))
              continue;
            seen[i]    = true;
            Point<3> x = cell->vertex(v);
            for (unsigned int c = 0; c < 3; ++c)
              x[c] += d_ghost[cell->vertex_dof_index(v, c)];
            const double e = x.distance(targets[i]);
            sum += e;
            max = std::max(max, e);
            n += 1;
          }
    n = Utilities::MPI::sum(n, comm);
    return {n > 0 ? Utilities::MPI::sum(sum, comm) / n : 0.,
            Utilities::MPI::max(max, comm)};
  }

  std::vector<double>
  ForwardProblem::image_mass_ratios() const
  {
    std::vector<double> ratios(
      labelled_mesh.triangulation().n_global_active_cells(), 0.);
    FEValues<3>                      fe_values(*mapping_,
                          fe_,
                          cell_quadrature,
                          update_gradients | update_JxW_values);
    std::vector<Tensor2>             grad_w(cell_quadrature.size());
    const FEValuesExtractors::Vector u(0);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_gradients(w_ghost, grad_w);
          double mesh_volume = 0, rest_volume = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              mesh_volume += fe_values.JxW(q);
              rest_volume +=
                determinant(Tensor2(unit_symmetric_tensor<3>()) + grad_w[q]) *
                fe_values.JxW(q);
            }
          ratios[labelled_mesh.cell_index(*cell)] =
            labelled_mesh.mass_ratio(*cell) * mesh_volume / rest_volume;
        }
    Utilities::MPI::sum(ratios, comm, ratios);
    return ratios;
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
          const MaterialLaw &law = material_table.law(cell->material_id());
          double             sum = 0, volume = 0;
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

  ForwardProblem::Compression
  ForwardProblem::most_compressed_cell() const
  {
    FEValues<3> fe_values(*mapping_, fe_, cell_quadrature, update_gradients);
    std::vector<Tensor2> grad_d(cell_quadrature.size()),
      grad_w(cell_quadrature.size());
    const FEValuesExtractors::Vector u(0);
    const Tensor2                    I = unit_symmetric_tensor<3>();
    Compression                      mine;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_gradients(d_ghost, grad_d);
          fe_values[u].get_function_gradients(w_ghost, grad_w);
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
        }
    Compression result;
    for (const auto &[det_F, where] :
         Utilities::MPI::all_gather(comm,
                                    std::make_pair(mine.det_F, mine.where)))
      if (det_F < result.det_F)
        result = {det_F, where};
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

  double
  ForwardProblem::potential_energy() const
  {
    return total_energy;
  }

  Tensor<1, 3>
  ForwardProblem::elastic_support_force() const
  {
    Tensor<1, 3> force;
    for (const auto &term : load_terms)
      if (term->is_support())
        force += term->local_resultant(current_load, d_ghost, w_ghost);
    for (unsigned int c = 0; c < 3; ++c)
      force[c] = Utilities::MPI::sum(force[c], comm);
    return force;
  }

  Tensor<1, 3>
  ForwardProblem::total_external_force(const LoadState &load) const
  {
    Tensor<1, 3> force;
    FEValues<3>  fv(*mapping_,
                   fe_,
                   cell_quadrature,
                   update_JxW_values | update_quadrature_points);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          for (const unsigned int q : fv.quadrature_point_indices())
            force +=
              body_force(*cell, fv.quadrature_point(q), load) * fv.JxW(q);
        }
    for (unsigned int c = 0; c < 3; ++c)
      force[c] = Utilities::MPI::sum(force[c], comm);
    return force + surface_force(load);
  }

  Tensor<1, 3>
  ForwardProblem::surface_force(const LoadState &load) const
  {
    Tensor<1, 3> force;
    for (const auto &term : load_terms)
      if (!term->is_support())
        force += term->local_resultant(load, d_ghost, w_ghost);
    for (unsigned int c = 0; c < 3; ++c)
      force[c] = Utilities::MPI::sum(force[c], comm);
    return force;
  }
} // namespace RestShape
