// The round trip of a rest shape through rest_shape.msh (see
// rest_shape_file.h).
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <restshape/app/rest_shape_file.h>
#include <restshape/mesh/gmsh_io.h>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Whether @p forward has quadratic tetrahedra.
    bool
    quadratic_tetrahedra(const ForwardProblem &forward)
    {
      const FiniteElement<3> &fe = forward.discretization().fe();
      return fe.reference_cell() == ReferenceCells::Tetrahedron &&
             fe.degree == 2;
    }

    /// The reference tetrahedron's vertices a and b of a support point
    /// @p p of a quadratic element that is an edge's midpoint; {a, a} for
    /// a vertex.
    std::pair<unsigned int, unsigned int>
    edge_of(const Point<3> &p)
    {
      const double lambda[4] = {1 - p[0] - p[1] - p[2], p[0], p[1], p[2]};
      std::vector<unsigned int> half;
      for (unsigned int v = 0; v < 4; ++v)
        {
          if (std::abs(lambda[v] - 1) < 1e-12)
            return {v, v};
          if (std::abs(lambda[v] - 0.5) < 1e-12)
            half.push_back(v);
        }
      AssertThrow(half.size() == 2, ExcMessage("not a P2 support point"));
      return {half[0], half[1]};
    }

    /// Calls @p f(dof, component, vertex a, vertex b, cell) for every DoF
    /// of every locally owned cell of @p forward (a == b at a vertex),
    /// quadratic tetrahedra only.
    template <typename Function>
    void
    for_each_dof(const ForwardProblem &forward, const Function &f)
    {
      const FiniteElement<3> &fe = forward.discretization().fe();
      const auto &support        = fe.base_element(0).get_unit_support_points();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell :
           forward.discretization().dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const auto [c, k] = fe.system_to_component_index(i);
                const auto [a, b] = edge_of(support[k]);
                f(dofs[i], c, a, b, cell);
              }
          }
    }

    /// Whether @p ok holds on every rank.
    bool
    everywhere(const ForwardProblem &forward, const bool ok)
    {
      return Utilities::MPI::min(ok ? 1 : 0,
                                 forward.discretization().communicator()) == 1;
    }
  } // namespace

  LabelledMesh::RestNodes
  rest_nodes_of(const ForwardProblem &forward)
  {
    LabelledMesh::RestNodes nodes;
    const DoFHandler<3> &dof_handler = forward.discretization().dof_handler();
    const VectorType    &d           = forward.displacement();
    const auto &vertices = dof_handler.get_triangulation().get_vertices();
    nodes.equilibria     = vertices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          for (unsigned int c = 0; c < 3; ++c)
            nodes.equilibria[cell->vertex_index(v)][c] =
              vertices[cell->vertex_index(v)][c] +
              d[cell->vertex_dof_index(v, c)];
    if (!quadratic_tetrahedra(forward))
      return nodes;
    // The edge nodes at the midpoints of gmsh's edges, in its order.
    const Point<3>        corner[4] = {Point<3>(0, 0, 0),
                                       Point<3>(1, 0, 0),
                                       Point<3>(0, 1, 0),
                                       Point<3>(0, 0, 1)};
    std::vector<Point<3>> midpoints;
    for (const auto &edge : gmsh_tet10_edges)
      midpoints.emplace_back((corner[edge[0]] + corner[edge[1]]) / 2);
    FEValues<3>                      values(forward.discretization().mapping(),
                       forward.discretization().fe(),
                       Quadrature<3>(midpoints),
                       update_values | update_quadrature_points);
    const FEValuesExtractors::Vector u(0);
    std::vector<Tensor<1, 3>>        w_at(6), d_at(6);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        values.reinit(cell);
        values[u].get_function_values(forward.rest_displacement(), w_at);
        values[u].get_function_values(d, d_at);
        std::array<Point<3>, 6> rest, equilibrium;
        for (unsigned int k = 0; k < 6; ++k)
          {
            rest[k]        = values.quadrature_point(k) + w_at[k];
            equilibrium[k] = values.quadrature_point(k) + d_at[k];
          }
        nodes.edge_rest.push_back(rest);
        nodes.edge_equilibria.push_back(equilibrium);
      }
    return nodes;
  }

  std::optional<VectorType>
  rest_shape_of_edge_nodes(const ForwardProblem &forward,
                           const LabelledMesh   &mesh)
  {
    if (!quadratic_tetrahedra(forward) ||
        mesh.rest_shape_nodes().edge_nodes.empty())
      return std::nullopt;
    const RestShapeNodeLookup lookup(mesh.rest_shape_nodes());
    VectorType                w     = forward.discretization().zero_vector();
    bool                      found = true;
    for_each_dof(forward,
                 [&](const auto         dof,
                     const unsigned int c,
                     const unsigned int a,
                     const unsigned int b,
                     const auto        &cell) {
                   if (a == b)
                     return;
                   const auto node =
                     lookup.edge_node(cell->vertex(a), cell->vertex(b));
                   found &= node.has_value();
                   if (node && w.in_local_range(dof))
                     w[dof] = (*node)[c] -
                              (cell->vertex(a)[c] + cell->vertex(b)[c]) / 2;
                 });
    w.compress(VectorOperation::insert);
    if (!everywhere(forward, found))
      return std::nullopt;
    return w;
  }

  std::optional<VectorType>
  equilibrium_of_rest_shape_file(const ForwardProblem &forward,
                                 const LabelledMesh   &mesh)
  {
    const RestShapeNodes &data = mesh.rest_shape_nodes();
    if (data.equilibria.empty())
      return std::nullopt;
    const RestShapeNodeLookup lookup(data);
    const auto               &vertices = mesh.triangulation().get_vertices();
    // The vertices' equilibria, linear between them ...
    std::vector<Tensor<1, 3>> shift(vertices.size());
    bool                      found = true;
    for (const auto &cell : mesh.triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto x = lookup.equilibrium(cell->vertex(v));
            found &= x.has_value();
            if (x)
              shift[cell->vertex_index(v)] = *x - cell->vertex(v);
          }
    if (!everywhere(forward, found))
      return std::nullopt;
    VectorType d = forward.discretization().interpolate_vertex_field(shift);
    // ... and each edge node's own where the file has the edge nodes.
    if (!quadratic_tetrahedra(forward) || !lookup.has_edge_nodes())
      return d;
    for_each_dof(forward,
                 [&](const auto         dof,
                     const unsigned int c,
                     const unsigned int a,
                     const unsigned int b,
                     const auto        &cell) {
                   if (a == b)
                     return;
                   const auto node =
                     lookup.edge_node(cell->vertex(a), cell->vertex(b));
                   const auto x = node ? lookup.equilibrium(*node) :
                                         std::optional<Point<3>>();
                   if (x && d.in_local_range(dof))
                     d[dof] =
                       (*x)[c] - (cell->vertex(a)[c] + cell->vertex(b)[c]) / 2;
                 });
    d.compress(VectorOperation::insert);
    return d;
  }
} // namespace RestShape
