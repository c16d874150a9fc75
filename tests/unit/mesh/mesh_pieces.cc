// Face-connected pieces of a mesh (source/mesh_pieces.cc), on meshes whose
// pieces are known by construction:
//  1. Three tetrahedra joined by faces and a fourth touching them at one
//     vertex only: two pieces of 3 and 1 cells.
//  2. remove_small_pieces with fraction 0.5 removes the single tetrahedron
//     and its three own vertices, renumbers the rest and keeps coordinates
//     and labels; with fraction 0.2 it removes nothing.
//  3. Hexahedra: two sharing a face are one piece, a third sharing only an
//     edge with them is a piece of its own.
//  4. Pinched boundary edges: none where cells share faces or only a
//     vertex; one where two tetrahedra, or two hexahedra, share only an
//     edge.
//  5. Gaps between folds of the surface: none on a convex body; a U of
//     cubes, its slot 1 wide and then 0.3; the committed coarse brain
//     against a Python ray caster written independently.
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/mesh_description.h>
#include <restshape/mesh/mesh_pieces.h>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  CellData<3>
  cell(const std::vector<unsigned int> &vertices, const unsigned int label)
  {
    CellData<3> c(vertices.size());
    c.vertices    = vertices;
    c.material_id = label;
    return c;
  }
} // namespace

int
main()
{
  MeshDescription tets;
  for (unsigned int v = 0; v < 8; ++v)
    tets.vertices.emplace_back(v, v * v, 1. / (v + 1));
  tets.cells              = {cell({0, 1, 2, 3}, 1),
                             cell({4, 5, 6, 7}, 2), // touches the others at vertex 4 only
                             cell({1, 2, 3, 4}, 1),
                             cell({0, 2, 3, 4}, 3)};
  const MeshPieces pieces = face_connected_pieces(tets);
  check_below("pieces - 2", std::abs(int(pieces.n_cells.size()) - 2), 0);
  check_below("cells in the largest piece - 3",
              std::abs(int(pieces.n_cells[0]) - 3),
              0);
  check_below("piece of the vertex-joined cell - 1",
              std::abs(int(pieces.piece_of_cell[1]) - 1),
              0);
  check_below("piece of the face-joined cells",
              pieces.piece_of_cell[0] + pieces.piece_of_cell[2] +
                pieces.piece_of_cell[3],
              0);

  MeshDescription     unchanged = tets;
  const RemovedPieces none      = remove_small_pieces(unchanged, 0.2);
  check_below("removed with fraction 0.2", none.n_cells + none.n_pieces, 0);
  check_below("cells kept with fraction 0.2 - 4",
              std::abs(int(unchanged.cells.size()) - 4),
              0);

  MeshDescription     cleaned = tets;
  const RemovedPieces removed = remove_small_pieces(cleaned, 0.5);
  check_below("removed pieces - 1", std::abs(int(removed.n_pieces) - 1), 0);
  check_below("removed cells - 1", std::abs(int(removed.n_cells) - 1), 0);
  check_below("vertices left - 5",
              std::abs(int(cleaned.vertices.size()) - 5),
              0);
  double mismatch = 0;
  for (unsigned int c = 0; c < 3; ++c)
    {
      const CellData<3> &before = tets.cells[c == 0 ? 0 : c + 1];
      const CellData<3> &after  = cleaned.cells[c];
      mismatch += std::abs(int(before.material_id) - int(after.material_id));
      for (unsigned int v = 0; v < 4; ++v)
        mismatch += tets.vertices[before.vertices[v]].distance(
          cleaned.vertices[after.vertices[v]]);
    }
  check_below("coordinates and labels of the kept cells", mismatch, 0);
  check_below("pieces after removal - 1",
              std::abs(int(face_connected_pieces(cleaned).n_cells.size()) - 1),
              0);

  // Hexahedra on a grid of unit cubes: [0,1]x[0,1]x[0,1] and
  // [1,2]x[0,1]x[0,1] share the face x = 1; [2,3]x[1,2]x[0,1] shares only
  // the edge x = 2, y = 1 with the second.
  MeshDescription hexes;
  for (unsigned int k = 0; k < 4; ++k)
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int i = 0; i < 4; ++i)
        hexes.vertices.emplace_back(i, j, k);
  const auto hex =
    [](const unsigned int i, const unsigned int j, const unsigned int k) {
      std::vector<unsigned int> v;
      for (unsigned int c = 0; c < 8; ++c) // deal.II's lexicographic order
        v.push_back((i + c % 2) + 4 * (j + (c / 2) % 2) + 12 * (k + c / 4));
      return cell(v, 1);
    };
  hexes.cells                 = {hex(0, 0, 0), hex(1, 0, 0), hex(2, 1, 0)};
  const MeshPieces hex_pieces = face_connected_pieces(hexes);
  check_below("hexahedral pieces - 2",
              std::abs(int(hex_pieces.n_cells.size()) - 2),
              0);
  check_below("face-joined hexahedra in one piece",
              hex_pieces.piece_of_cell[0] + hex_pieces.piece_of_cell[1],
              0);
  check_below("edge-joined hexahedron on its own - 1",
              std::abs(int(hex_pieces.piece_of_cell[2]) - 1),
              0);

  check_below("pinched edges of tetrahedra joined by faces or a vertex",
              n_pinched_boundary_edges(tets),
              0);
  MeshDescription edge_joined = tets;
  edge_joined.cells           = {cell({0, 1, 2, 3}, 1), cell({0, 1, 4, 5}, 1)};
  check_below("pinched edges of two edge-joined tetrahedra - 1",
              std::abs(int(n_pinched_boundary_edges(edge_joined)) - 1),
              0);
  check_below("pinched edges of hexahedra with an edge-joined one - 1",
              std::abs(int(n_pinched_boundary_edges(hexes)) - 1),
              0);
  hexes.cells.pop_back();
  check_below("pinched edges of two face-joined hexahedra",
              n_pinched_boundary_edges(hexes),
              0);

  // Gaps between folds of the surface. Two face-joined cubes (convex): no
  // ray from the surface meets it again.
  check_below("gap faces of a convex body",
              narrowest_surface_gap(hexes, 10).n_narrow,
              0);
  // A U of five cubes: the arms [0,1]x[1,2] and [2,3]x[1,2] face each
  // other across a slot 1 wide.
  hexes.cells = {hex(0, 0, 0), hex(1, 0, 0), hex(2, 0, 0), hex(0, 1, 0)};
  hexes.cells.push_back(hex(2, 1, 0));
  const SurfaceGap slot = narrowest_surface_gap(hexes, 1.5);
  check_below("U: slot width - 1", std::abs(slot.width - 1), 1e-12);
  check_below("U: faces across the slot - 2",
              std::abs(int(slot.n_narrow) - 2),
              0);
  check_below("U: gap on an arm's inner face (x = 1 or 2, y = 1.5, z = 0.5)",
              std::min(std::abs(slot.location[0] - 1),
                       std::abs(slot.location[0] - 2)) +
                std::abs(slot.location[1] - 1.5) +
                std::abs(slot.location[2] - 0.5),
              1e-12);
  // Narrow the slot to 0.3: the right arm's inner face moves to x = 1.3
  // (the base cubes below it become skewed, still valid).
  for (Point<3> &x : hexes.vertices)
    if (x[0] == 2 && x[1] >= 1)
      x[0] = 1.3;
  check_below("U narrowed: slot width - 0.3",
              std::abs(narrowest_surface_gap(hexes, 1.5).width - 0.3),
              1e-12);

  // Tetrahedra: the committed coarse brain. Its narrowest gap (above a
  // flap at the base of the left frontal lobe) was measured independently
  // with a Python ray caster: 1.344288 mm from the face at
  // (-6.2077, 11.3087, -28.2529) mm; 17 faces below 3 mm (two of them hit
  // the surface on an edge shared by two triangles).
  const MeshDescription brain     = read_gmsh("meshes/brain_coarse.msh", 1e-3);
  const SurfaceGap      brain_gap = narrowest_surface_gap(brain, 3e-3);
  std::cout << "brain: narrowest gap " << brain_gap.width * 1e3 << " mm at "
            << brain_gap.location * 1e3 << " mm, " << brain_gap.n_narrow
            << " faces below 3 mm" << std::endl;
  check_below("brain: narrowest gap - 1.344288 mm (mm)",
              std::abs(brain_gap.width * 1e3 - 1.344288),
              1e-5);
  check_below("brain: its location (mm)",
              brain_gap.location.distance(Point<3>(-6.2077, 11.3087, -28.2529) *
                                          1e-3) *
                1e3,
              1e-3);
  check_below("brain: faces below 3 mm - 17",
              std::abs(int(brain_gap.n_narrow) - 17),
              0);
  return exit_code();
}
