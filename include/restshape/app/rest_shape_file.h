// The round trip of a rest shape through rest_shape.msh: what an inverse
// run writes besides the vertices (each node's equilibrium; the edge nodes
// of quadratic tetrahedra, whose edges are curved in a P2 rest shape), and
// what a forward run from the file takes from it (the rest positions of
// the edge nodes; the equilibrium as Newton's start).
#ifndef restshape_app_rest_shape_file_h
#define restshape_app_rest_shape_file_h

#include <restshape/forward/forward_problem.h>
#include <restshape/mesh/labelled_mesh.h>

#include <optional>

namespace RestShape
{
  /// The equilibrium of every vertex and, on quadratic tetrahedra, the
  /// rest and equilibrium positions of every cell's edge nodes, at the
  /// state of @p forward (for LabelledMesh::write_gmsh(); one rank).
  LabelledMesh::RestNodes
  rest_nodes_of(const ForwardProblem &forward);

  /**
   * A forward run on quadratic tetrahedra from a rest_shape.msh whose
   * cells carry edge nodes: the rest displacement (owned, m) that puts
   * each edge's node where the file has it (zero at the vertices, whose
   * positions are the mesh's). nullopt where the mesh has no edge nodes,
   * the element is not quadratic or an edge is not in the file (a
   * refined mesh).
   */
  std::optional<VectorType>
  rest_shape_of_edge_nodes(const ForwardProblem &forward,
                           const LabelledMesh   &mesh);

  /**
   * A forward run from a rest_shape.msh that carries the equilibrium of
   * each node: that equilibrium as a displacement from the mesh (owned,
   * m), for Newton's start. nullopt where the file has none or a node is
   * not in it.
   */
  std::optional<VectorType>
  equilibrium_of_rest_shape_file(const ForwardProblem &forward,
                                 const LabelledMesh   &mesh);
} // namespace RestShape

#endif
