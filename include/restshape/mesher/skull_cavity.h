// The cavity of a segmented skull: the region a binary skull mask encloses,
// whose boundary is the skull's inner surface (restshape-mesh
// --skull-image).
#ifndef restshape_mesher_skull_cavity_h
#define restshape_mesher_skull_cavity_h

#include <restshape/mesher/labelled_image.h>

#include <string>

namespace RestShape
{
  /**
   * The largest face-connected region of voxels of @p mask that are not
   * skull (label 0) and cannot be reached from the image's border through
   * such voxels, as label 1 on the mask's grid. Throws InputError naming
   * @p file and @p option when the mask encloses no voxel (a skull open to
   * the outside, e.g. at the foramen magnum, must be closed in the mask).
   */
  LabelledImage
  skull_cavity(const LabelledImage &mask,
               const std::string   &file,
               const std::string   &option);
} // namespace RestShape

#endif
