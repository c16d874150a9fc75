// Meshing a labelled image with CGAL Mesh_3 (labelled-image domain), the
// quality report of a tetrahedral mesh, and the offset surface that encloses
// the labelled region (the skull's inner surface beyond a CSF layer).
#ifndef restshape_image_mesher_h
#define restshape_image_mesher_h

#include <restshape/mesh/labelled_mesh.h>
#include <restshape/mesher/components.h>
#include <restshape/mesher/labelled_image.h>

#include <map>
#include <string>

namespace RestShape
{
  /// Mesh_3 criteria, all lengths in mm.
  /// CGAL's global mesh optimisers (--optimise).
  enum class MeshOptimiser
  {
    none,
    odt,  // optimal Delaunay triangulation smoothing
    lloyd // Lloyd (centroidal Voronoi) smoothing
  };

  struct ImageMeshOptions
  {
    double cell_size  = 10; // largest tetrahedron circumradius
    double facet_size = 10; // largest surface-triangle circumradius
    double facet_distance =
      1.5; // largest distance between facet and image boundary
    double facet_angle  = 25;    // smallest surface-triangle angle (degrees)
    double radius_edge  = 3;     // largest circumradius / shortest edge
    double sliver_bound = 12;    // dihedral angle (degrees) that perturbation
                                 // and exudation try to exceed
    unsigned int  seed      = 0; // CGAL's random seed: same input, same mesh
    MeshOptimiser optimiser = MeshOptimiser::none;
    unsigned int  optimiser_iterations = 10; // of ODT or Lloyd
  };

  /**
   * Tetrahedral mesh of the labelled region of @p image: every cell carries
   * the label of the image region it lies in (its material_id). Every
   * connected component of @p components (image_components(image)) and
   * every cavity larger than least_component_volume() is meshed; labels
   * on the image's border keep their outer half voxel. Vertices
   * in mm, in the image's world coordinates (sform/qform honoured; cells are
   * positively oriented even when the map mirrors).
   */
  MeshDescription
  mesh_labelled_image(const LabelledImage    &image,
                      const ImageMeshOptions &options,
                      const ImageComponents  &components);

  /**
   * The same for an image the caller no longer needs: its labels are freed
   * once CGAL has its own copy (in the smallest word that holds them),
   * which lowers the mesher's peak memory by 4 bytes per voxel.
   */
  MeshDescription
  mesh_labelled_image(LabelledImage         &&image,
                      const ImageMeshOptions &options,
                      const ImageComponents  &components);

  struct MeshQuality
  {
    double       min_dihedral_deg = 180;
    double       max_dihedral_deg = 0;
    double       max_radius_edge  = 0;
    double       mean_radius_edge = 0;
    unsigned int n_below_10_deg = 0; // cells with a dihedral angle < 10 degrees
    double       min_volume     = 0; // in the mesh's length unit cubed
    double       total_volume   = 0;
    std::map<unsigned int, double> volume_per_label;
    /// The cells of the smallest dihedral angles, worst first: (angle in
    /// degrees, cell index).
    std::vector<std::pair<double, unsigned int>> worst_cells;
  };

  /// Dihedral angles, circumradius-to-shortest-edge ratios and volumes.
  MeshQuality
  mesh_quality(const MeshDescription &tets);

  /**
   * Write to @p file (.stl, .off or .obj, mm) a closed, outward-oriented
   * triangulated surface enclosing every labelled voxel of @p image at
   * @p gap mm from the boundary of the labelled region after a morphological
   * closing with a ball of radius @p closing mm (which bridges sulci and
   * fissures, as the skull does; 0: no closing): the level set
   * {distance = gap} of the Euclidean distance transform, meshed by Mesh_3
   * with facets of at most @p facet_size mm within @p facet_distance mm of
   * that level set. Returns the number of triangles.
   */
  unsigned int
  write_enclosing_surface(const LabelledImage &image,
                          const double         gap,
                          const double         closing,
                          const double         facet_size,
                          const double         facet_distance,
                          const std::string   &file);
} // namespace RestShape

#endif
