// Morphology on voxel grids: the exact Euclidean distance transform
// (Felzenszwalb and Huttenlocher 2012), the closing with a ball, and the
// closing of a labelled image, which fills sulci narrower than the mesh
// before meshing (narrow sulci become pinched edges of the mesh's surface,
// where CSF pressure crushes the cells).
#ifndef restshape_image_morphology_h
#define restshape_image_morphology_h

#include <restshape/mesher/labelled_image.h>

#include <array>
#include <cstddef>
#include <vector>

namespace RestShape
{
  /// A box of voxels, i fastest, with edge lengths h (mm).
  struct VoxelGrid
  {
    std::array<unsigned int, 3> n;
    std::array<double, 3>       h;

    std::size_t
    at(const unsigned int i, const unsigned int j, const unsigned int k) const
    {
      return i + std::size_t(n[0]) * (j + std::size_t(n[1]) * k);
    }

    std::size_t
    size() const
    {
      return std::size_t(n[0]) * n[1] * n[2];
    }
  };

  /// Exact Euclidean distance (mm) from every voxel centre of @p grid to the
  /// nearest centre of a voxel of @p mask (1e10 when @p mask is empty).
  std::vector<double>
  distance_to(const std::vector<bool> &mask, const VoxelGrid &grid);

  /// Morphological closing of @p mask with a ball of @p radius mm: dilate,
  /// then erode. Voxels within @p radius of the grid's border are not
  /// eroded from outside the grid: pad the grid when the mask comes close.
  void
  close_with_ball(std::vector<bool> &mask,
                  const VoxelGrid   &grid,
                  const double       radius);

  struct ClosedVoxels
  {
    std::size_t n_added    = 0;
    double      volume_mm3 = 0;
  };

  /**
   * Close the labelled region of @p image (all non-zero labels together)
   * with a ball of @p radius mm, which fills sulci and gaps narrower than
   * about twice the radius. Every added voxel takes the label most common
   * among its labelled neighbours (26-neighbourhood), grown layer by layer
   * from the existing labels; existing labels do not change.
   */
  ClosedVoxels
  close_labelled_image(LabelledImage &image, const double radius);
  /// 6-neighbours of voxel v of @p image (those inside the grid).
  template <typename F>
  void
  for_neighbours(const LabelledImage &image, const std::size_t v, const F &f)
  {
    const std::size_t nx = image.size[0], ny = image.size[1],
                      nz = image.size[2];
    const std::size_t i = v % nx, j = (v / nx) % ny, k = v / (nx * ny);
    if (i > 0)
      f(v - 1);
    if (i + 1 < nx)
      f(v + 1);
    if (j > 0)
      f(v - nx);
    if (j + 1 < ny)
      f(v + nx);
    if (k > 0)
      f(v - nx * ny);
    if (k + 1 < nz)
      f(v + nx * ny);
  }


  /// Face-connected components (6-connectivity) of the voxels where @p in
  /// is true: the component index of every voxel (-1 outside) and the
  /// components' sizes.
  std::pair<std::vector<int>, std::vector<std::size_t>>
  face_connected_components(const LabelledImage     &image,
                            const std::vector<bool> &in);
} // namespace RestShape

#endif
