#include <restshape/base/input_error.h>
#include <restshape/mesher/skull_cavity.h>

#include <algorithm>
#include <vector>

namespace RestShape
{
  namespace
  {
    /// Label the face-connected components of the voxels where @p free is
    /// true (1, 2, ...; 0 elsewhere) and return their sizes (index 0
    /// unused).
    std::vector<std::size_t>
    components(const LabelledImage       &image,
               const std::vector<bool>   &free,
               std::vector<unsigned int> &component)
    {
      const auto &n = image.size;
      component.assign(free.size(), 0);
      std::vector<std::size_t> sizes = {0};
      std::vector<std::size_t> stack;
      for (std::size_t start = 0; start < free.size(); ++start)
        {
          if (!free[start] || component[start] != 0)
            continue;
          sizes.push_back(0);
          component[start] = sizes.size() - 1;
          stack.push_back(start);
          while (!stack.empty())
            {
              const std::size_t v = stack.back();
              stack.pop_back();
              ++sizes.back();
              const std::size_t i = v % n[0], j = (v / n[0]) % n[1],
                                k       = v / (std::size_t(n[0]) * n[1]);
              const long        step[3] = {1, long(n[0]), long(n[0]) * n[1]};
              const std::size_t at[3]   = {i, j, k};
              for (unsigned int d = 0; d < 3; ++d)
                for (const int s : {-1, 1})
                  {
                    if ((s < 0 && at[d] == 0) || (s > 0 && at[d] + 1 == n[d]))
                      continue;
                    const std::size_t w = v + s * step[d];
                    if (free[w] && component[w] == 0)
                      {
                        component[w] = component[start];
                        stack.push_back(w);
                      }
                  }
            }
        }
      return sizes;
    }
  } // namespace

  LabelledImage
  skull_cavity(const LabelledImage &mask,
               const std::string   &file,
               const std::string   &option)
  {
    const auto       &n = mask.size;
    std::vector<bool> free(mask.labels.size());
    for (std::size_t v = 0; v < free.size(); ++v)
      free[v] = mask.labels[v] == 0;
    std::vector<unsigned int>      component;
    const std::vector<std::size_t> sizes = components(mask, free, component);
    // Components that touch the border are outside the skull.
    std::vector<bool> outside(sizes.size(), false);
    for (unsigned int k = 0; k < n[2]; ++k)
      for (unsigned int j = 0; j < n[1]; ++j)
        for (unsigned int i = 0; i < n[0]; ++i)
          if (i == 0 || j == 0 || k == 0 || i + 1 == n[0] || j + 1 == n[1] ||
              k + 1 == n[2])
            outside[component[mask.index(i, j, k)]] = true;
    unsigned int largest = 0;
    for (unsigned int c = 1; c < sizes.size(); ++c)
      if (!outside[c] && (largest == 0 || sizes[c] > sizes[largest]))
        largest = c;
    if (largest == 0)
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
