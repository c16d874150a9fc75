// Connected components of a labelled image and of its mesh, to see that
// the mesh kept every region and cavity the image has.
#ifndef restshape_mesher_components_h
#define restshape_mesher_components_h

#include <restshape/mesh/mesh_description.h>
#include <restshape/mesher/labelled_image.h>

#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace RestShape
{
  /// The 6-connected components of an image's labels.
  struct ImageComponents
  {
    /// Per label > 0: the voxels of each component, largest first.
    std::map<unsigned int, std::vector<std::size_t>> voxels;
    /// The voxels of each cavity (a component of label 0 that does not
    /// reach the image's border), largest first.
    std::vector<std::size_t> cavities;
    /// Per cavity (in the order of cavities), the voxel of it nearest its
    /// centroid (i, j, k).
    std::vector<std::array<unsigned int, 3>> cavity_voxels;
  };

  ImageComponents
  image_components(const LabelledImage &image);

  /// The face-connected pieces of a mesh's labels and its boundary
  /// surfaces (boundary faces connected across edges).
  struct MeshComponents
  {
    /// Per label: the volume of each piece (mesh units^3), largest first.
    std::map<unsigned int, std::vector<double>> volumes;
    /// The volume each boundary surface encloses (1/3 sum x.n dA with the
    /// body's outward normals): positive for an outer surface, negative
    /// for the wall of a cavity.
    std::vector<double> surfaces;
    /// The boundary faces (vertex indices, outward oriented) and the
    /// index in surfaces of each one's surface.
    std::vector<std::array<unsigned int, 3>> boundary_faces;
    std::vector<unsigned int>                face_surface;

    unsigned int
    n_cavities() const;
    /// Whether boundary face @p f lies on the wall of a cavity.
    bool
    on_cavity_wall(const unsigned int f) const
    {
      return surfaces[face_surface[f]] < 0;
    }
  };

  MeshComponents
  mesh_components(const MeshDescription &mesh);

  /// The least volume (mm^3) of a component that must be in the mesh: a
  /// few (8) tetrahedra of @p cell_size (mm; a quarter of its cube each).
  inline double
  least_component_volume(const double cell_size)
  {
    constexpr double few_cells = 8, tetrahedron_share = 0.25;
    return few_cells * tetrahedron_share * cell_size * cell_size * cell_size;
  }

  /**
   * The image's components against the mesh's: a line per label (its
   * components and volume in both) and one for the boundary surfaces, on
   * @p report; "" if the mesh kept every component and cavity larger than
   * @p least_volume (mm^3), else what it lost (one line). @p voxel_volume:
   * mm^3 per voxel; @p name: label -> text for messages.
   */
  std::string
  compare_components(const ImageComponents &image,
                     const MeshComponents  &mesh,
                     const double           voxel_volume,
                     const double           least_volume,
                     const std::function<std::string(unsigned int)> &name,
                     std::ostream                                   &report);
} // namespace RestShape

#endif
