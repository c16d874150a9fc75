// What a rest_shape.msh adds to its mesh beyond the vertices: the rest
// positions of the edge nodes of quadratic tetrahedra (a P2 rest shape has
// curved edges) and the equilibrium every node reached in the inverse run
// that wrote the file. Both are keyed by positions in the mesh, so that
// they survive any renumbering, sorting or partition of its cells.
#ifndef restshape_mesh_rest_shape_nodes_h
#define restshape_mesh_rest_shape_nodes_h

#include <deal.II/base/point.h>

#include <array>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace RestShape
{
  /// The data as read (flat, to pass through a pipe and copy with a mesh).
  struct RestShapeNodes
  {
    /// Triples: the two ends of an edge and the rest position of its
    /// node (m).
    std::vector<dealii::Point<3>> edge_nodes;
    /// Pairs: a node's position in the mesh (a vertex, or an edge node at
    /// its rest position) and its equilibrium position (m).
    std::vector<dealii::Point<3>> equilibria;

    bool
    empty() const
    {
      return edge_nodes.empty() && equilibria.empty();
    }
  };

  /// Look-ups into RestShapeNodes by exact positions.
  class RestShapeNodeLookup
  {
  public:
    explicit RestShapeNodeLookup(const RestShapeNodes &nodes);

    /// The rest position of the node of the edge from @p a to @p b.
    std::optional<dealii::Point<3>>
    edge_node(const dealii::Point<3> &a, const dealii::Point<3> &b) const;
    /// The equilibrium position of the node at @p p.
    std::optional<dealii::Point<3>>
    equilibrium(const dealii::Point<3> &p) const;
    bool
    has_edge_nodes() const
    {
      return !edges.empty();
    }
    bool
    has_equilibria() const
    {
      return !nodes.empty();
    }

  private:
    using Key = std::array<double, 3>;
    static Key
    key(const dealii::Point<3> &p)
    {
      return {{p[0], p[1], p[2]}};
    }
    std::map<std::pair<Key, Key>, dealii::Point<3>> edges;
    std::map<Key, dealii::Point<3>>                 nodes;
  };
} // namespace RestShape

#endif
