// Face-connected pieces of a mesh. Cells joined to the rest of a body only
// at a vertex or an edge (as Mesh_3 leaves them where labelled voxels touch
// diagonally) can rotate about that hinge without resistance, which stops
// Newton's method on fine brain meshes: the mesher removes them, and
// LabelledMesh warns about them in meshes from elsewhere. Pinched boundary
// edges are the other topological defect of meshes of folded surfaces.
#ifndef restshape_mesh_pieces_h
#define restshape_mesh_pieces_h

#include <restshape/mesh/labelled_mesh.h>

#include <limits>
#include <set>
#include <string>
#include <vector>

namespace RestShape
{
  struct MeshPieces
  {
    /// For every cell, its piece; piece 0 is the largest.
    std::vector<unsigned int> piece_of_cell;
    /// Number of cells per piece, largest first.
    std::vector<unsigned int> n_cells;
  };

  /**
   * Split the cells of @p mesh (tetrahedra or hexahedra) into pieces in
   * which any two cells are joined by a chain of cells sharing faces.
   */
  MeshPieces
  face_connected_pieces(const MeshDescription &mesh);

  /// A face-connected piece that nothing holds against rigid motion.
  struct UnheldPiece
  {
    unsigned int     n_cells = 0;
    std::set<Label>  labels;
    dealii::Point<3> centre; // of its vertices (mesh units)
    /// Vertices it shares with held pieces: 0 (it floats), 1 (it pivots
    /// about a point) or more on a line (it hinges about an edge).
    unsigned int n_joints = 0;

    /// "a piece of 120 cells (label 3) around (40, 5, 10) floats freely".
    std::string
    text(const double unit_to_mm) const;
  };

  /**
   * The pieces of @p mesh that no cell of @p held_labels holds, directly or
   * through at least three non-collinear vertices shared with a held piece
   * (a piece joined to the rest at one vertex or along an edge can still
   * rotate about it).
   */
  std::vector<UnheldPiece>
  unheld_pieces(const MeshDescription &mesh,
                const MeshPieces      &pieces,
                const std::set<Label> &held_labels);

  struct RemovedPieces
  {
    unsigned int n_pieces = 0;
    unsigned int n_cells  = 0;
  };

  /**
   * Remove the pieces with fewer cells than @p fraction times the largest
   * one, and the vertices no cell uses any more. Labels are kept; separate
   * bodies of comparable size stay.
   */
  RemovedPieces
  remove_small_pieces(MeshDescription &mesh, const double fraction);

  /**
   * The number of pinched boundary edges of @p mesh (tetrahedra or
   * hexahedra): edges shared by more than two boundary faces, where two
   * sheets of the surface touch along an edge (a sulcus narrower than the
   * mesh). Pressure on both sheets, right up to the pinch, crushes the cells
   * there.
   */
  unsigned int
  n_pinched_boundary_edges(const MeshDescription &mesh);

  /// The vertices on the boundary of @p mesh (on a face of one cell only).
  std::set<unsigned int>
  boundary_vertices(const MeshDescription &mesh);

  struct SurfaceGap
  {
    /// Narrowest width (mesh units); infinity if no ray meets the surface.
    double width = std::numeric_limits<double>::infinity();
    /// Centroid of the surface face it starts from.
    dealii::Point<3> location;
    /// Surface faces whose gap is narrower than the threshold asked for.
    unsigned int n_narrow = 0;
  };

  /**
   * The narrowest gap between folds of the surface of @p mesh (tetrahedra
   * or hexahedra): from the centroid of every boundary face, a ray along
   * its outward normal (away from its cell's centroid) to the first other
   * boundary face it meets (CGAL AABB tree; quadrilaterals split in two
   * triangles). A sulcus narrower than the cells leaves thin flaps of
   * tissue, one cell thick, on both sides; their knife edges are where
   * solutions on refined meshes do not converge and have more than one
   * equilibrium (doc/benchmarks.md). Faces narrower than @p threshold are
   * counted.
   */
  SurfaceGap
  narrowest_surface_gap(const MeshDescription &mesh, const double threshold);

  /// "narrowest gap between folds of the surface: W mm, from the face at X
  /// Y Z mm", the line both programs print (arguments in mm).
  std::string
  describe_surface_gap(const double width_mm, const dealii::Point<3> &where_mm);
} // namespace RestShape

#endif
