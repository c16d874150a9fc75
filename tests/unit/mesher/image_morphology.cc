// Voxel morphology (source/image_morphology.cc) against results known by
// construction:
//  1. distance_to on an anisotropic grid (h = 1, 2, 0.5 mm) from a single
//     voxel equals the Euclidean distance between voxel centres everywhere.
//  2. close_labelled_image with a ball of 1.5 mm on two boxes (labels 1 and
//     3, 6x6 voxels in cross-section) 2 voxels apart fills exactly the gap
//     but for its 8 voxels along the boxes' edges (a voxel there is 1.41 mm
//     from a voxel 1.73 mm from both boxes, which the dilation does not
//     reach): 64 voxels, 64 mm^3. The layer next to label 1 gets label 1,
//     the one next to label 3 gets label 3; no labelled voxel changes.
//  3. The same boxes 5 voxels apart: nothing is added.
#include <restshape/mesher/image_morphology.h>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  /// A 20x10x10 image of 1 mm voxels with label 1 on i in [2, 7] and label 3
  /// on i in [first_3, first_3 + 5], both on j, k in [2, 7].
  LabelledImage
  two_boxes(const unsigned int first_3)
  {
    LabelledImage image;
    image.size = {{20, 10, 10}};
    for (unsigned int d = 0; d < 3; ++d)
      image.index_to_mm[d][d] = 1;
    image.labels.assign(20 * 10 * 10, 0);
    for (unsigned int k = 2; k <= 7; ++k)
      for (unsigned int j = 2; j <= 7; ++j)
        for (unsigned int i = 0; i < 20; ++i)
          if (i >= 2 && i <= 7)
            image.labels[image.index(i, j, k)] = 1;
          else if (i >= first_3 && i <= first_3 + 5)
            image.labels[image.index(i, j, k)] = 3;
    return image;
  }
} // namespace

int
main()
{
  const VoxelGrid   grid{{{7, 5, 3}}, {{1, 2, 0.5}}};
  std::vector<bool> mask(grid.size(), false);
  mask[grid.at(2, 3, 1)]          = true;
  const std::vector<double> dist  = distance_to(mask, grid);
  double                    error = 0;
  for (unsigned int k = 0; k < 3; ++k)
    for (unsigned int j = 0; j < 5; ++j)
      for (unsigned int i = 0; i < 7; ++i)
        {
          const double exact = std::sqrt(std::pow(1. * (int(i) - 2), 2) +
                                         std::pow(2. * (int(j) - 3), 2) +
                                         std::pow(0.5 * (int(k) - 1), 2));
          error = std::max(error, std::abs(dist[grid.at(i, j, k)] - exact));
        }
  check_below("distance transform error (mm)", error, 1e-12);

  const LabelledImage before = two_boxes(10);
  LabelledImage       after  = before;
  const ClosedVoxels  closed = close_labelled_image(after, 1.5);
  check_below("voxels added to a 2-voxel gap - 64",
              std::abs(double(closed.n_added) - 64),
              0);
  check_below("volume added - 64 mm^3",
              std::abs(closed.volume_mm3 - 64),
              1e-12);
  unsigned int wrong = 0;
  for (unsigned int k = 0; k < 10; ++k)
    for (unsigned int j = 0; j < 10; ++j)
      for (unsigned int i = 0; i < 20; ++i)
        {
          const std::size_t v       = before.index(i, j, k);
          const bool        on_edge = (j == 2 || j == 7) && (k == 2 || k == 7);
          const bool        in_gap  = (i == 8 || i == 9) && j >= 2 && j <= 7 &&
                              k >= 2 && k <= 7 && !on_edge;
          const unsigned int expect =
            in_gap ? (i == 8 ? 1 : 3) : before.labels[v];
          wrong += after.labels[v] != expect;
        }
  check_below("voxels with another label than expected", wrong, 0);

  LabelledImage      apart        = two_boxes(13);
  const ClosedVoxels closed_apart = close_labelled_image(apart, 1.5);
  check_below("voxels added to a 5-voxel gap", closed_apart.n_added, 0);
  check_below("labels changed with a 5-voxel gap",
              apart.labels != two_boxes(13).labels,
              0);
  return exit_code();
}
