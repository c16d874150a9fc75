// TargetRelaxation: the admissible target's shift, smoothed where the
// projection onto the obstacle inverts cells.
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <restshape/contact/target_relaxation.h>
#include <restshape/fem/nodal_norms.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace RestShape
{
  using namespace dealii;

  TargetRelaxation::TargetRelaxation(const Discretization &discretization,
                                     const Obstacle       &obstacle)
    : discretization(discretization)
    , obstacle(obstacle)
  {
    collect_cell_nodes();
  }

  void
  TargetRelaxation::collect_cell_nodes()
  {
    const auto &nodes = discretization.relevant_nodes();
    std::map<types::global_dof_index, unsigned int> node_of_dof;
    node_fixed.assign(nodes.size(), true);
    for (unsigned int n = 0; n < nodes.size(); ++n)
      {
        node_of_dof[nodes[n].dofs[0]] = n;
        for (const auto dof : nodes[n].dofs)
          node_fixed[n] = node_fixed[n] && discretization.is_fixed(dof);
      }
    const auto &fe   = discretization.fe();
    const auto &base = fe.base_element(0);
    weight           = discretization.vertex_weights();
    n_vertices       = weight.front().size();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell :
         discretization.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          std::vector<unsigned int> mine(base.n_dofs_per_cell());
          for (unsigned int b = 0; b < mine.size(); ++b)
            mine[b] = node_of_dof.at(dofs[fe.component_to_system_index(0, b)]);
          cell_nodes.push_back(mine);
        }
  }

  std::pair<unsigned int, unsigned int>
  TargetRelaxation::mark_inverted(const VectorType  &shift,
                                  std::vector<char> &in_set,
                                  std::string       *where) const
  {
    const auto  &nodes = discretization.relevant_nodes();
    FEValues<3>  fe_values(discretization.mapping(),
                          discretization.fe(),
                          discretization.quadrature(),
                          update_gradients);
    VectorType   marked = writable();
    unsigned int n_bad = 0, n_inverted = 0, c = 0;
    std::string  first;
    for (const auto &cell :
         discretization.dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const std::vector<unsigned int> &mine = cell_nodes[c++];
        // A cell none of whose nodes moved keeps det = 1.
        if (std::none_of(mine.begin(), mine.end(), [&](unsigned int n) {
              return shift[nodes[n].dofs[0]] != 0 ||
                     shift[nodes[n].dofs[1]] != 0 ||
                     shift[nodes[n].dofs[2]] != 0;
            }))
          continue;
        fe_values.reinit(cell);
        const double least =
          Discretization::smallest_jacobian(fe_values, shift);
        if (least >= minimum_jacobian)
          continue;
        ++n_bad;
        if (least <= 0 && n_inverted++ == 0)
          first = cell_location_text(cell->material_id(), cell->center());
        // Vertices join once the cell's other nodes are in the set.
        const bool others_in =
          std::all_of(mine.begin() + n_vertices, mine.end(), [&](unsigned n) {
            return in_set[n] || node_fixed[n];
          });
        for (unsigned int b = 0; b < mine.size(); ++b)
          if (!node_fixed[mine[b]] && (b >= n_vertices || others_in))
            marked[nodes[mine[b]].dofs[0]] += 1.;
      }
    marked.compress(VectorOperation::add);
    const VectorType ghosted = discretization.ghosted_copy(marked);
    for (unsigned int n = 0; n < nodes.size(); ++n)
      in_set[n] = in_set[n] || ghosted[nodes[n].dofs[0]] > 0;
    const MPI_Comm comm =
      discretization.mesh().triangulation().get_communicator();
    n_bad      = Utilities::MPI::sum(n_bad, comm);
    n_inverted = Utilities::MPI::sum(n_inverted, comm);
    if (where != nullptr)
      for (const std::string &text : Utilities::MPI::all_gather(comm, first))
        if (!text.empty())
          {
            *where = text;
            break;
          }
    return {n_bad, n_inverted};
  }

  VectorType
  TargetRelaxation::sweep(const VectorType        &shift,
                          const std::vector<char> &in_set) const
  {
    const auto &nodes = discretization.relevant_nodes();
    VectorType  sum = writable(), count = writable();
    VectorType  push = writable(), pushes = writable();
    auto        add = [&](VectorType         &v,
                   VectorType         &c,
                   unsigned int        n,
                   const Tensor<1, 3> &value) {
      for (unsigned int k = 0; k < 3; ++k)
        {
          v[nodes[n].dofs[k]] += value[k];
          c[nodes[n].dofs[k]] += 1.;
        }
    };
    for (const std::vector<unsigned int> &mine : cell_nodes)
      {
        if (std::none_of(mine.begin(), mine.end(), [&](unsigned int n) {
              return in_set[n];
            }))
          continue;
        std::vector<Tensor<1, 3>> vertex(n_vertices);
        Tensor<1, 3>              mean;
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            for (unsigned int k = 0; k < 3; ++k)
              vertex[v][k] = shift[nodes[mine[v]].dofs[k]];
            mean += vertex[v] / n_vertices;
          }
        for (unsigned int b = 0; b < mine.size(); ++b)
          {
            if (!in_set[mine[b]])
              continue;
            if (b < n_vertices)
              {
                add(sum, count, mine[b], mean);
                continue;
              }
            // A node on an edge, face or inside: the vertices' linear
            // interpolation; where that lies beyond the obstacle, the
            // vertices are pushed so that it does not.
            Tensor<1, 3> value;
            double       norm = 0;
            for (unsigned int v = 0; v < n_vertices; ++v)
              {
                value += weight[b][v] * vertex[v];
                norm += weight[b][v] * weight[b][v];
              }
            add(sum, count, mine[b], value);
            const Gap g = obstacle.gap(nodes[mine[b]].position + value);
            if (g.gap < 0)
              for (unsigned int v = 0; v < n_vertices; ++v)
                if (weight[b][v] != 0 && !node_fixed[mine[v]])
                  add(push,
                      pushes,
                      mine[v],
                      -g.gap * weight[b][v] / norm * g.gradient);
          }
      }
    for (VectorType *v : {&sum, &count, &push, &pushes})
      v->compress(VectorOperation::add);
    VectorType      result = discretization.owned_copy(shift);
    const IndexSet &owned  = discretization.locally_owned_dofs();
    for (unsigned int n = 0; n < nodes.size(); ++n)
      if (owned.is_element(nodes[n].dofs[0]) &&
          count[nodes[n].dofs[0]] + pushes[nodes[n].dofs[0]] > 0)
        {
          const Node  &node = nodes[n];
          Tensor<1, 3> value;
          for (unsigned int k = 0; k < 3; ++k)
            {
              const auto dof = node.dofs[k];
              value[k] = count[dof] > 0 ? sum[dof] / count[dof] : shift[dof];
              if (pushes[dof] > 0)
                value[k] += push[dof] / pushes[dof];
            }
          keep_inside(node.position, value);
          for (unsigned int k = 0; k < 3; ++k)
            result[node.dofs[k]] = discretization.is_fixed(node.dofs[k]) ?
                                     shift[node.dofs[k]] :
                                     value[k];
        }
    result.compress(VectorOperation::insert);
    return result;
  }

  VectorType
  TargetRelaxation::writable() const
  {
    VectorType v;
    v.reinit(discretization.locally_owned_dofs(),
             discretization.locally_relevant_dofs(),
             discretization.mesh().triangulation().get_communicator(),
             true);
    return v;
  }

  void
  TargetRelaxation::keep_inside(const Point<3> &position,
                                Tensor<1, 3>   &shift) const
  {
    const Gap g = obstacle.gap(position + shift);
    if (g.gap < 0)
      shift -= g.gap * g.gradient;
  }

  TargetRelaxationResult
  TargetRelaxation::relax(VectorType &shift) const
  {
    TargetRelaxationResult result;
    const auto            &nodes = discretization.relevant_nodes();
    const MPI_Comm         comm =
      discretization.mesh().triangulation().get_communicator();
    std::vector<char> in_set(nodes.size(), 0);
    const VectorType  projected = discretization.owned_copy(shift);
    VectorType        ghosted   = discretization.ghosted_copy(shift);
    std::tie(result.below_threshold, result.inverted_before) =
      mark_inverted(ghosted, in_set, &result.where);
    // The set's size over all ranks (nodes shared by ranks counted on
    // each): every rank takes the same decisions below.
    const auto set_size = [&]() {
      return Utilities::MPI::sum(static_cast<unsigned int>(
                                   std::count(in_set.begin(), in_set.end(), 1)),
                                 comm);
    };
    // Sweep until no cell is below the threshold, or until none is
    // inverted and neither the set nor the count of cells below it has
    // changed for a while (a smoothed state the sweeps do not improve).
    // An empty set (every node of those cells fixed) cannot change.
    unsigned int stalled = 0, inverted = result.inverted_before;
    while (result.below_threshold > 0 && result.sweeps < max_sweeps &&
           (inverted > 0 || stalled < patience) && set_size() > 0)
      {
        shift = sweep(ghosted, in_set);
        ++result.sweeps;
        ghosted                 = shift;
        const auto size_before  = set_size();
        const auto below_before = result.below_threshold;
        std::tie(result.below_threshold, inverted) =
          mark_inverted(ghosted, in_set, &result.where);
        const bool same =
          below_before == result.below_threshold && size_before == set_size();
        stalled = same ? stalled + 1 : 0;
      }
    // Hanging nodes follow their parents; fixed DoFs stay. The counts
    // then describe the target the inverse iteration aims at.
    discretization.base_constraints().distribute(shift);
    ghosted = shift;
    std::tie(result.below_threshold, result.inverted_after) =
      mark_inverted(ghosted, in_set, &result.where);
    VectorType change = discretization.owned_copy(shift);
    change -= projected;
    const auto moved =
      nodal_norms_above(discretization, change, negligible_change);
    result.moved_nodes    = moved.n;
    result.largest_change = moved.max;
    return result;
  }
} // namespace RestShape
