#include <deal.II/distributed/tria.h>
#include <deal.II/grid/tria_accessor.h>

#include <restshape/forward/state_transfer.h>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// The affine map of a tetrahedron: p = v0 + J xi (deal.II's reference
    /// tetrahedron, vertex k at xi = e_k).
    Tensor<2, 3>
    jacobian(const std::array<Point<3>, 4> &v)
    {
      Tensor<2, 3> J;
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int i = 0; i < 3; ++i)
          J[i][k] = v[k + 1][i] - v[0][i];
      return J;
    }
  } // namespace

  StateTransfer::StateTransfer(const ForwardProblem                  &forward,
                               const std::vector<const VectorType *> &fields)
    : n_fields(fields.size())
  {
    const DoFHandler<3> &dofs = forward.discretization().dof_handler();
    const auto          &tria = dofs.get_triangulation();
    if (forward.discretization().mesh().is_simplex())
      {
        std::vector<VectorType> relevant(n_fields);
        for (std::size_t f = 0; f < n_fields; ++f)
          relevant[f] = forward.discretization().ghosted_copy(
            forward.discretization().owned_copy(*fields[f]));
        const unsigned int dofs_per_cell =
          forward.discretization().fe().n_dofs_per_cell();
        std::vector<types::global_dof_index> indices(dofs_per_cell);
        n_old_cells = tria.n_global_active_cells();
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              OldCell &old =
                old_cells[forward.discretization().mesh().cell_index(*cell)];
              for (unsigned int v = 0; v < 4; ++v)
                old.vertices[v] = cell->vertex(v);
              cell->get_dof_indices(indices);
              old.values.reserve(n_fields * dofs_per_cell);
              for (std::size_t f = 0; f < n_fields; ++f)
                for (const auto i : indices)
                  old.values.push_back(relevant[f][i]);
            }
        return;
      }

    for (const VectorType *field : fields)
      {
        inputs.emplace_back(forward.discretization().locally_owned_dofs(),
                            forward.discretization().locally_relevant_dofs(),
                            tria.get_communicator());
        const VectorType owned = forward.discretization().owned_copy(*field);
        inputs.back()          = owned; // not a temporary: see above
      }
    if (dynamic_cast<const parallel::distributed::Triangulation<3> *>(&tria))
      {
        distributed = std::make_unique<
          parallel::distributed::SolutionTransfer<3, VectorType>>(dofs);
        std::vector<const VectorType *> in;
        for (const VectorType &v : inputs)
          in.push_back(&v);
        distributed->prepare_for_coarsening_and_refinement(in);
      }
    else
      {
        serial = std::make_unique<SolutionTransfer<3, VectorType>>(dofs);
        serial->prepare_for_coarsening_and_refinement(inputs);
      }
  }

  StateTransfer::~StateTransfer() = default;

  std::vector<VectorType>
  StateTransfer::interpolate(const ForwardProblem &forward)
  {
    std::vector<VectorType> out;
    if (forward.discretization().mesh().is_simplex())
      out = interpolate_tetrahedra(forward);
    else
      {
        out.assign(n_fields, forward.discretization().zero_vector());
        if (distributed)
          {
            std::vector<VectorType *> pointers;
            for (VectorType &v : out)
              pointers.push_back(&v);
            distributed->interpolate(pointers);
          }
        else
          serial->interpolate(inputs, out);
      }
    for (VectorType &v : out)
      {
        v.compress(VectorOperation::insert);
        forward.discretization().base_constraints().distribute(v);
      }
    return out;
  }

  std::vector<VectorType>
  StateTransfer::interpolate_tetrahedra(const ForwardProblem &forward) const
  {
    const DoFHandler<3> &dofs          = forward.discretization().dof_handler();
    const FESystem<3>   &fe            = forward.discretization().fe();
    const unsigned int   dofs_per_cell = fe.n_dofs_per_cell();
    AssertThrow(dofs.get_triangulation().n_global_active_cells() ==
                  8 * n_old_cells,
                ExcMessage("StateTransfer: a tetrahedral mesh must be "
                           "refined once, every cell into eight"));
    const IndexSet &owned = forward.discretization().locally_owned_dofs();
    std::vector<VectorType>              out(n_fields,
                                forward.discretization().zero_vector());
    std::vector<bool>                    done(owned.n_elements(), false);
    std::vector<types::global_dof_index> indices(dofs_per_cell);
    std::vector<double>                  shape(dofs_per_cell);
    const std::vector<Point<3>>         &support = fe.get_unit_support_points();
    for (const auto &cell : dofs.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const OldCell &parent =
          old_cells.at(forward.discretization().mesh().cell_index(*cell) / 8);
        const auto              J     = jacobian(parent.vertices);
        const auto              J_inv = invert(J);
        std::array<Point<3>, 4> vertices;
        for (unsigned int v = 0; v < 4; ++v)
          vertices[v] = cell->vertex(v);
        const auto J_cell = jacobian(vertices);
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            if (!owned.is_element(indices[i]) ||
                done[owned.index_within_set(indices[i])])
              continue;
            done[owned.index_within_set(indices[i])] = true;
            const Point<3> x = vertices[0] + J_cell * support[i];
            const Point<3> xi(J_inv * (x - parent.vertices[0]));
            AssertThrow(xi[0] > -1e-8 && xi[1] > -1e-8 && xi[2] > -1e-8 &&
                          xi[0] + xi[1] + xi[2] < 1 + 1e-8,
                        ExcMessage("StateTransfer: a refined tetrahedron is "
                                   "not inside its parent"));
            const unsigned int component =
              fe.system_to_component_index(i).first;
            for (unsigned int j = 0; j < dofs_per_cell; ++j)
              shape[j] = fe.shape_value_component(j, xi, component);
            for (std::size_t f = 0; f < n_fields; ++f)
              {
                double value = 0;
                for (unsigned int j = 0; j < dofs_per_cell; ++j)
                  value += parent.values[f * dofs_per_cell + j] * shape[j];
                out[f][indices[i]] = value;
              }
          }
      }
    return out;
  }
} // namespace RestShape
