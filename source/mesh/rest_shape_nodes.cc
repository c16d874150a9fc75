// RestShapeNodeLookup: the edge nodes and equilibria of a rest_shape.msh
// by position (see rest_shape_nodes.h).
#include <restshape/mesh/rest_shape_nodes.h>

#include <algorithm>

namespace RestShape
{
  RestShapeNodeLookup::RestShapeNodeLookup(const RestShapeNodes &data)
  {
    for (std::size_t i = 0; i + 2 < data.edge_nodes.size(); i += 3)
      edges[std::minmax(key(data.edge_nodes[i]), key(data.edge_nodes[i + 1]))] =
        data.edge_nodes[i + 2];
    for (std::size_t i = 0; i + 1 < data.equilibria.size(); i += 2)
      nodes[key(data.equilibria[i])] = data.equilibria[i + 1];
  }

  std::optional<dealii::Point<3>>
  RestShapeNodeLookup::edge_node(const dealii::Point<3> &a,
                                 const dealii::Point<3> &b) const
  {
    const auto it = edges.find(std::minmax(key(a), key(b)));
    if (it == edges.end())
      return std::nullopt;
    return it->second;
  }

  std::optional<dealii::Point<3>>
  RestShapeNodeLookup::equilibrium(const dealii::Point<3> &p) const
  {
    const auto it = nodes.find(key(p));
    if (it == nodes.end())
      return std::nullopt;
    return it->second;
  }
} // namespace RestShape
