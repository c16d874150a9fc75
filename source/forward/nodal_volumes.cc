// NodalVolumes: the vertices' volumes of the averaged nodal pressure
// tetrahedron, their pressures and their stiffness.

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <restshape/base/outer_product.h>
#include <restshape/forward/nodal_volumes.h>

#include <algorithm>
#include <set>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    constexpr unsigned int vertices_per_cell = 4;
    constexpr unsigned int dofs_per_cell     = 12;
    // A vertex's share of the volume of a cell around it.
    constexpr double vertex_share = 1.0 / vertices_per_cell;
    // The volume of a tetrahedron is a sixth of its edges' triple product.
    constexpr double tetrahedron_volume = 1.0 / 6.0;

    /// Whether some DoF of @p patch is constrained in @p constraints.
    bool
    any_constrained(const std::vector<types::global_dof_index> &patch,
                    const AffineConstraints<double>            &constraints)
    {
      return std::any_of(patch.begin(), patch.end(), [&](const auto i) {
        return constraints.is_constrained(i);
      });
    }
  } // namespace

  void
  NodalVolumes::reinit(const DoFHandler<3> &dof_handler,
                       const BufferType    &like,
                       const bool           boundary_to_interior)
  {
    const FiniteElement<3> &fe = dof_handler.get_fe();
    AssertThrow(fe.n_dofs_per_cell() == dofs_per_cell,
                ExcMessage("averaged nodal pressure: linear tetrahedra only"));
    const auto &partitioner = *like.get_partitioner();
    cells.clear();
    of_cell.assign(dof_handler.get_triangulation().n_active_cells(), -1);
    owned_vertex.clear();
    patches.clear();
    std::vector<int> slot(partitioner.locally_owned_size(), -1);
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    // The labels of this process's cells, once each: compute_set_union
    // keeps a single process's duplicates, and a vector per duplicate
    // was 16 % of the brain's mixed forward solve on 25,173 DoFs.
    std::set<unsigned int> labels;
    for (const auto &dof_cell : dof_handler.active_cell_iterators())
      {
        if (dof_cell->is_artificial())
          continue;
        dof_cell->get_dof_indices(dofs);
        Cell c;
        c.label = dof_cell->material_id();
        c.owned = dof_cell->is_locally_owned();
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const auto [component, vertex] = fe.system_to_component_index(i);
            c.dofs[3 * vertex + component] = dofs[i];
            c.local[3 * vertex + component] =
              partitioner.global_to_local(dofs[i]);
          }
        for (unsigned int v = 0; v < vertices_per_cell; ++v)
          c.vertices[v] = dof_cell->vertex(v);
        const Tensor<1, 3> a = c.vertices[1] - c.vertices[0],
                           b = c.vertices[2] - c.vertices[0],
                           e = c.vertices[3] - c.vertices[0];
        c.orientation        = a * cross_product_3d(b, e) > 0 ? 1 : -1;
        of_cell[dof_cell->active_cell_index()] = cells.size();
        labels.insert(c.label);
        cells.push_back(c);
      }
    if (boundary_to_interior)
      set_shares(dof_handler, like);
    // A vertex's patch: the cells that give it a share of their volume.
    for (unsigned int index = 0; index < cells.size(); ++index)
      for (unsigned int v = 0; v < vertices_per_cell; ++v)
        {
          const unsigned int x = cells[index].local[3 * v];
          if (x >= partitioner.locally_owned_size() ||
              cells[index].share[v] == 0)
            continue;
          if (slot[x] < 0)
            {
              slot[x] = patches.size();
              owned_vertex.push_back(x);
              patches.emplace_back();
            }
          patches[slot[x]].push_back(index);
        }
    known = false;
    linear_change.reinit(like);
    // Every rank holds a vector per label of any rank: compress is
    // collective.
    volumes.clear();
    for (const unsigned int label :
         Utilities::MPI::compute_set_union(labels,
                                           partitioner.get_mpi_communicator()))
      volumes[Label(label)].reinit(like);
  }

  void
  NodalVolumes::set_shares(const DoFHandler<3> &dof_handler,
                           const BufferType    &like)
  {
    // A boundary vertex's own patch is a few cells, and its one volume
    // ratio holds their volumes much as a pressure per cell would: the
    // element locked there (the Lame shell at nu = 0.4999: 7.0, 7.1,
    // 7.5 % on 2, 1.6, 1.4 mm). Its share goes to the cell's interior
    // vertices instead; under a homogeneous state every vertex still has
    // the one volume ratio (the patch test).
    BufferType on_boundary(like);
    for (const auto &dof_cell : dof_handler.active_cell_iterators())
      if (dof_cell->is_locally_owned())
        {
          const Cell &c = cells[of_cell[dof_cell->active_cell_index()]];
          for (const unsigned int f : dof_cell->face_indices())
            if (dof_cell->at_boundary(f))
              for (unsigned int v = 0; v < vertices_per_cell; ++v)
                for (const unsigned int fv :
                     dof_cell->face(f)->vertex_indices())
                  if (dof_cell->face(f)->vertex_index(fv) ==
                      dof_cell->vertex_index(v))
                    on_boundary.local_element(c.local[3 * v]) = 1;
        }
    on_boundary.compress(VectorOperation::max);
    on_boundary.update_ghost_values();
    for (Cell &c : cells)
      {
        unsigned int interior = 0;
        for (unsigned int v = 0; v < vertices_per_cell; ++v)
          interior += on_boundary.local_element(c.local[3 * v]) == 0;
        for (unsigned int v = 0; v < vertices_per_cell; ++v)
          c.share[v] =
            interior == 0 ?
              vertex_share :
              (on_boundary.local_element(c.local[3 * v]) == 0 ? 1.0 / interior :
                                                                0.0);
      }
  }

  unsigned int
  NodalVolumes::vertex_of(const Cell &cell, const unsigned int x)
  {
    unsigned int v = 0;
    while (v + 1 < vertices_per_cell && cell.local[3 * v] != x)
      ++v;
    return v;
  }

  void
  NodalVolumes::add_sparsity(DynamicSparsityPattern          &dsp,
                             const AffineConstraints<double> &constraints) const
  {
    std::vector<types::global_dof_index> patch;
    for (const std::vector<unsigned int> &around : patches)
      {
        patch.clear();
        for (const unsigned int c : around)
          patch.insert(patch.end(), cells[c].dofs.begin(), cells[c].dofs.end());
        std::sort(patch.begin(), patch.end());
        patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
        // Unconstrained: each row's sorted columns at once (entry by entry,
        // as AffineConstraints adds them, was two thirds of the set-up).
        if (!any_constrained(patch, constraints))
          for (const auto row : patch)
            dsp.add_entries(row, patch.begin(), patch.end(), true);
        else
          constraints.add_entries_local_to_global(patch, dsp, true);
      }
  }

  std::array<Point<3>, 4>
  NodalVolumes::positions(const Cell &cell, const BufferType &u)
  {
    std::array<Point<3>, vertices_per_cell> x;
    for (unsigned int v = 0; v < vertices_per_cell; ++v)
      for (unsigned int c = 0; c < 3; ++c)
        x[v][c] = cell.vertices[v][c] + u.local_element(cell.local[3 * v + c]);
    return x;
  }

  double
  NodalVolumes::volume(const Cell &cell, const BufferType &u)
  {
    const std::array<Point<3>, vertices_per_cell> x = positions(cell, u);
    return cell.orientation * tetrahedron_volume * (x[1] - x[0]) *
           cross_product_3d(x[2] - x[0], x[3] - x[0]);
  }

  std::array<double, 12>
  NodalVolumes::volume_gradient(const Cell &cell, const BufferType &u)
  {
    const std::array<Point<3>, vertices_per_cell> x = positions(cell, u);
    const Tensor<1, 3> a = x[1] - x[0], b = x[2] - x[0], e = x[3] - x[0];
    // d(a . (b x e)): b x e at vertex 1, e x a at 2, a x b at 3, minus
    // their sum at 0.
    const std::array<Tensor<1, 3>, 3> partial = {
      {cross_product_3d(b, e), cross_product_3d(e, a), cross_product_3d(a, b)}};
    const double           scale = cell.orientation * tetrahedron_volume;
    std::array<double, 12> g;
    for (unsigned int c = 0; c < 3; ++c)
      {
        g[c] = -scale * (partial[0][c] + partial[1][c] + partial[2][c]);
        for (unsigned int v = 1; v < vertices_per_cell; ++v)
          g[3 * v + c] = scale * partial[v - 1][c];
      }
    return g;
  }

  void
  NodalVolumes::update(const BufferType    &d,
                       const BufferType    &w,
                       const MaterialTable &materials)
  {
    for (auto &[label, v] : volumes)
      v = 0;
    for (const Cell &c : cells)
      if (c.owned)
        {
          BufferType  &v       = volumes.at(c.label);
          const double rest    = volume(c, w);
          const double current = volume(c, d);
          for (unsigned int i = 0; i < vertices_per_cell; ++i)
            {
              v.local_element(c.local[3 * i]) += c.share[i] * rest;
              v.local_element(c.local[3 * i + 1]) += c.share[i] * current;
            }
        }
    for (auto &[label, v] : volumes)
      {
        v.compress(VectorOperation::add);
        v.update_ghost_values();
      }
    evaluated.resize(linear_change.locally_owned_size() +
                     linear_change.get_partitioner()->n_ghost_indices());
    std::vector<bool> done(evaluated.size(), false);
    for (const Cell &c : cells)
      for (unsigned int v = 0; v < vertices_per_cell; ++v)
        if (const unsigned int x = c.local[3 * v]; !done[x])
          {
            evaluated[x] = evaluate_vertex(x, c.local[3 * v + 1], materials);
            done[x]      = true;
          }
    if (known)
      predict_changes(d);
  }

  void
  NodalVolumes::predict_changes(const BufferType &d)
  {
    linear_change = 0;
    for (unsigned int index = 0; index < cells.size(); ++index)
      if (cells[index].owned)
        {
          const Cell &c      = cells[index];
          double      change = 0;
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            change += gradient0[index][i] *
                      (d.local_element(c.local[i]) - d0[index][i]);
          for (unsigned int v = 0; v < vertices_per_cell; ++v)
            linear_change.local_element(c.local[3 * v]) += c.share[v] * change;
        }
    linear_change.compress(VectorOperation::add);
    linear_change.update_ghost_values();
  }

  void
  NodalVolumes::record_linearisation(const BufferType &d)
  {
    gradient0.resize(cells.size());
    d0.resize(cells.size());
    pressure0.resize(linear_change.locally_owned_size() +
                     linear_change.get_partitioner()->n_ghost_indices());
    stiffness0.resize(pressure0.size());
    known = false; // vertex() gives the condensed pressures
    for (unsigned int index = 0; index < cells.size(); ++index)
      {
        const Cell &c    = cells[index];
        gradient0[index] = volume_gradient(c, d);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          d0[index][i] = d.local_element(c.local[i]);
        for (unsigned int v = 0; v < vertices_per_cell; ++v)
          {
            const Vertex n  = vertex(c, v);
            const auto   at = c.local[3 * v];
            pressure0[at]   = n.pressure;
            stiffness0[at]  = n.stiffness;
          }
      }
    known = true;
  }

  NodalVolumes::Vertex
  NodalVolumes::vertex(const Cell        &cell,
                       const unsigned int v,
                       const bool         shifted) const
  {
    const unsigned int x      = cell.local[3 * v];
    Vertex             result = evaluated[x];
    if (!result.valid)
      return result;
    if (shifted && x < offsets.size())
      result.pressure += offsets[x];
    result.predicted =
      known ? pressure0[x] + stiffness0[x] * linear_change.local_element(x) :
              result.pressure;
    return result;
  }

  NodalVolumes::Vertex
  NodalVolumes::evaluate_vertex(const unsigned int   x,
                                const unsigned int   y,
                                const MaterialTable &materials) const
  {
    Vertex result;
    double current = 0;
    for (const auto &[label, volume] : volumes)
      {
        result.rest += volume.local_element(x);
        current += volume.local_element(y);
      }
    if (result.rest == 0) // a boundary vertex without a share: no ratio
      {
        result.J = 1;
        return result;
      }
    result.J = current / result.rest;
    if (!(result.J > 0 && result.rest > 0))
      return result;
    // Each label's volumetric energy on its share of the rest volume, at
    // the vertex's one volume ratio.
    for (const auto &[label, volume] : volumes)
      if (const double share = volume.local_element(x); share > 0)
        {
          const MaterialLaw::Volumetric U =
            materials.law(label).volumetric(result.J);
          result.pressure += share / result.rest * U.dU;
          result.stiffness += share / (result.rest * result.rest) * U.d2U;
        }
    result.valid = true;
    return result;
  }

  std::vector<PressurePoint>
  NodalVolumes::pressure_points() const
  {
    std::vector<PressurePoint> points(
      linear_change.locally_owned_size() +
      linear_change.get_partitioner()->n_ghost_indices());
    for (const Cell &c : cells)
      for (unsigned int v = 0; v < vertices_per_cell; ++v)
        {
          const Vertex n         = vertex(c, v, false);
          points[c.local[3 * v]] = {n.J, n.pressure, n.stiffness * n.rest};
        }
    return points;
  }

  NodalVolumes::CellPressure
  NodalVolumes::cell(const unsigned int   cell,
                     const MaterialTable &materials,
                     const double         rest_volume) const
  {
    const Cell        &c   = cells[of_cell[cell]];
    const MaterialLaw &law = materials.law(c.label);
    CellPressure       result;
    for (unsigned int v = 0; v < vertices_per_cell; ++v)
      {
        if (c.share[v] == 0)
          continue;
        const Vertex n = vertex(c, v);
        if (!n.valid)
          {
            result.valid = false;
            return result;
          }
        result.pressure += c.share[v] * n.pressure;
        result.predicted += c.share[v] * n.predicted;
        result.energy += c.share[v] * rest_volume * law.volumetric(n.J).U;
      }
    return result;
  }

  void
  NodalVolumes::add_stiffness(const BufferType                &d,
                              const MaterialTable             &materials,
                              const AffineConstraints<double> &constraints,
                              TrilinosWrappers::SparseMatrix  &tangent,
                              BufferType                      &rhs,
                              PressureCoupling                *coupling,
                              SplitTangent                    *split) const
  {
    std::vector<types::global_dof_index> patch;
    std::vector<double>                  g;
    FullMatrix<double>                   M;
    Vector<double>                       no_rhs;
    for (unsigned int s = 0; s < patches.size(); ++s)
      {
        patch.clear();
        g.clear();
        for (const unsigned int index : patches[s])
          {
            const Cell                  &c      = cells[index];
            const std::array<double, 12> g_cell = volume_gradient(c, d);
            const double share = c.share[vertex_of(c, owned_vertex[s])];
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const auto at =
                  std::find(patch.begin(), patch.end(), c.dofs[i]);
                if (at == patch.end())
                  {
                    patch.push_back(c.dofs[i]);
                    g.push_back(share * g_cell[i]);
                  }
                else
                  g[at - patch.begin()] += share * g_cell[i];
              }
          }
        const Cell  &first  = cells[patches[s].front()];
        const double factor = evaluated[owned_vertex[s]].stiffness;
        if (coupling != nullptr)
          {
            // (A vertex between labels: those of its first cell.)
            const MaterialLaw &law = materials.law(first.label);
            coupling->add(patch,
                          g.data(),
                          coupled_fraction(law.mu, law.bulk_modulus) * factor,
                          constraints);
          }
        if (split != nullptr)
          split->add_term(factor, patch, g, constraints);
        if (!any_constrained(patch, constraints))
          add_outer_product(factor, patch, g, tangent);
        else
          {
            const unsigned int n = patch.size();
            M.reinit(n, n);
            no_rhs.reinit(n);
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                M(i, j) = factor * g[i] * g[j];
            constraints.distribute_local_to_global(
              M, no_rhs, patch, tangent, rhs);
          }
      }
  }
} // namespace RestShape
