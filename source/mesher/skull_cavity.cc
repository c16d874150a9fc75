#include <restshape/base/input_error.h>
#include <restshape/mesher/image_morphology.h>
#include <restshape/mesher/skull_cavity.h>

#include <algorithm>
#include <vector>

namespace RestShape
{
  LabelledImage
  skull_cavity(const LabelledImage &mask,
               const std::string   &file,
               const std::string   &option)
  {
    const auto       &n = mask.size;
    std::vector<bool> free(mask.labels.size());
    for (std::size_t v = 0; v < free.size(); ++v)
      free[v] = mask.labels[v] == 0;
    const auto [component, sizes] = face_connected_components(mask, free);
    // Components that touch the border are outside the skull.
    std::vector<bool> outside(sizes.size(), false);
    for (unsigned int k = 0; k < n[2]; ++k)
      for (unsigned int j = 0; j < n[1]; ++j)
        for (unsigned int i = 0; i < n[0]; ++i)
          if (i == 0 || j == 0 || k == 0 || i + 1 == n[0] || j + 1 == n[1] ||
              k + 1 == n[2])
            {
              const int c = component[mask.index(i, j, k)];
              if (c >= 0)
                outside[c] = true;
            }
    int largest = -1;
    for (unsigned int c = 0; c < sizes.size(); ++c)
      if (!outside[c] && (largest < 0 || sizes[c] > sizes[largest]))
        largest = c;
    if (largest < 0)
      throw InputError(file,
                       option,
                       "the skull mask encloses no cavity (every voxel "
                       "outside the skull is connected to the image's "
                       "border); expected a closed skull: close its openings "
                       "(e.g. the foramen magnum) in the mask");
    LabelledImage cavity = mask;
    for (std::size_t v = 0; v < cavity.labels.size(); ++v)
      cavity.labels[v] = component[v] == largest ? 1 : 0;
    return cavity;
  }
} // namespace RestShape
