// restshape-brain-labels: the labelled brain image of the paper's scene,
// built from Debian's mricron-data (Colin27 on the MNI grid).
//
//   restshape-brain-labels --brain ch2bet.nii.gz --atlas aal.nii.gz
//       --out LABELS.nii.gz [--tumour X,Y,Z --tumour-radius MM]
//       [--brainstem-half-width MM]
//
// Labels: 1 cerebrum, 2 tumour, 3 cerebellum, 4 brainstem.
//  - brain: the largest connected component of the non-zero voxels of
//    --brain, its cavities filled;
//  - cerebellum: AAL indices 91-116 (cerebellum and vermis);
//  - cerebrum: AAL indices 1-90;
//  - brainstem: brain voxels without an AAL index, below the lowest cerebral
//    voxel and within --brainstem-half-width mm of the midline (x = 0);
//  - the remaining brain voxels (white matter, unlabelled rim) take the label
//    of the nearest labelled voxel;
//  - tumour: the brain voxels within --tumour-radius mm of --tumour (MNI mm);
//  - finally every label keeps only its largest connected piece; the other
//    pieces are given to their neighbours, so that each region is one solid.
#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/mesher/image_morphology.h>
#include <restshape/mesher/labelled_image.h>

#include <algorithm>
#include <deque>
#include <iostream>

namespace
{
  /// --help: the usage comment at the top of this file.
  const char *const usage =
    "restshape-brain-labels: the labelled brain image of the paper's scene,\n"
    "built from Debian's mricron-data (Colin27 on the MNI grid).\n"
    "\n"
    "  restshape-brain-labels --brain ch2bet.nii.gz --atlas aal.nii.gz\n"
    "      --out LABELS.nii.gz [--tumour X,Y,Z --tumour-radius MM]\n"
    "      [--brainstem-half-width MM]\n"
    "\n"
    "Labels: 1 cerebrum, 2 tumour, 3 cerebellum, 4 brainstem.\n"
    " - brain: the largest connected component of the non-zero voxels of\n"
    "   --brain, its cavities filled;\n"
    " - cerebellum: AAL indices 91-116 (cerebellum and vermis);\n"
    " - cerebrum: AAL indices 1-90;\n"
    " - brainstem: brain voxels without an AAL index, below the lowest cerebral\n"
    "   voxel and within --brainstem-half-width mm of the midline (x = 0);\n"
    " - the remaining brain voxels (white matter, unlabelled rim) take the label\n"
    "   of the nearest labelled voxel;\n"
    " - tumour: the brain voxels within --tumour-radius mm of --tumour (MNI mm);\n"
    " - finally every label keeps only its largest connected piece; the other\n"
    "   pieces are given to their neighbours, so that each region is one solid.\n";
} // namespace

using namespace RestShape;

namespace
{
  constexpr ImageLabel cerebrum = 1, tumour = 2, cerebellum = 3, brainstem = 4,
                       unknown = 255;

  /// Give every brain voxel labelled `unknown` the label of the nearest
  /// (in 6-connected steps through the brain) labelled voxel.
  void
  fill_unknown(LabelledImage &labels)
  {
    std::deque<std::size_t> queue;
    for (std::size_t v = 0; v < labels.labels.size(); ++v)
      if (labels.labels[v] != 0 && labels.labels[v] != unknown)
        queue.push_back(v);
    while (!queue.empty())
      {
        const std::size_t v = queue.front();
        queue.pop_front();
        for_neighbours(labels, v, [&](const std::size_t w) {
          if (labels.labels[w] == unknown)
            {
              labels.labels[w] = labels.labels[v];
              queue.push_back(w);
            }
        });
      }
  }

} // namespace

int
main(int argc, char **argv)
{
  try
    {
      const ToolOptions cl(argc,
                           argv,
                           {"--brain",
                            "--atlas",
                            "--out",
                            "--tumour",
                            "--tumour-radius",
                            "--brainstem-half-width"});
      if (cl.help())
        {
          std::cout << usage;
          return 0;
        }
      const std::string brain_file =
        cl.required("--brain", "a brain mask, e.g. ch2bet.nii.gz");
      const std::string atlas_file =
        cl.required("--atlas", "a labelled atlas, e.g. aal.nii.gz");
      const std::string out =
        cl.required("--out", "the output image, e.g. LABELS.nii.gz");
      const std::array<double, 3> centre =
        cl.triple("--tumour", {{-32, 28, 28}});
      const double radius     = cl.positive("--tumour-radius", 12);
      const double half_width = cl.positive("--brainstem-half-width", 16);

      const LabelledImage brain = read_labelled_image(brain_file, "--brain");
      const LabelledImage atlas = read_labelled_image(atlas_file, "--atlas");
      if (brain.size != atlas.size ||
          (brain.index_to_mm - atlas.index_to_mm).norm() > 1e-6 ||
          (brain.offset - atlas.offset).norm() > 1e-6)
        throw InputError(
          atlas_file,
          "--atlas",
          "not on the grid of --brain; expected both on the same voxel grid");

      const std::size_t n = brain.labels.size();
      // The brain: largest component of the mask, cavities filled.
      std::vector<bool> in(n);
      for (std::size_t v = 0; v < n; ++v)
        in[v] = brain.labels[v] != 0;
      {
        const auto [component, sizes] = face_connected_components(brain, in);
        const int largest =
          std::max_element(sizes.begin(), sizes.end()) - sizes.begin();
        for (std::size_t v = 0; v < n; ++v)
          in[v] = component[v] == largest;
      }
      {
        std::vector<bool> out_of_brain(n);
        for (std::size_t v = 0; v < n; ++v)
          out_of_brain[v] = !in[v];
        const auto [component, sizes] =
          face_connected_components(brain, out_of_brain);
        const int outside = component[0]; // the corner voxel is background
        for (std::size_t v = 0; v < n; ++v)
          if (!in[v] && component[v] != outside)
            in[v] = true;
      }

      LabelledImage labels          = brain;
      unsigned int  lowest_cerebral = brain.size[2];
      for (std::size_t v = 0; v < n; ++v)
        if (in[v] && atlas.labels[v] >= 1 && atlas.labels[v] <= 90)
          lowest_cerebral = std::min<unsigned int>(
            lowest_cerebral, v / (std::size_t(brain.size[0]) * brain.size[1]));
      for (unsigned int k = 0; k < brain.size[2]; ++k)
        for (unsigned int j = 0; j < brain.size[1]; ++j)
          for (unsigned int i = 0; i < brain.size[0]; ++i)
            {
              const std::size_t v = brain.index(i, j, k);
              const ImageLabel  a = atlas.labels[v];
              ImageLabel       &l = labels.labels[v];
              if (!in[v])
                l = 0;
              else if (a >= 91 && a <= 116)
                l = cerebellum;
              else if (a >= 1 && a <= 90)
                l = cerebrum;
              else if (k < lowest_cerebral &&
                       std::abs(brain.position(i, j, k)[0]) < half_width)
                l = brainstem;
              else
                l = unknown;
            }
      fill_unknown(labels);
      for (unsigned int k = 0; k < brain.size[2]; ++k)
        for (unsigned int j = 0; j < brain.size[1]; ++j)
          for (unsigned int i = 0; i < brain.size[0]; ++i)
            {
              const std::size_t v = brain.index(i, j, k);
              const auto        x = brain.position(i, j, k);
              if (in[v] && x.distance(dealii::Point<3>(centre[0],
                                                       centre[1],
                                                       centre[2])) <= radius)
                labels.labels[v] = tumour;
            }

      // One connected piece per label.
      for (const ImageLabel label : {cerebrum, tumour, cerebellum, brainstem})
        {
          std::vector<bool> mine(n);
          for (std::size_t v = 0; v < n; ++v)
            mine[v] = labels.labels[v] == label;
          const auto [component, sizes] =
            face_connected_components(labels, mine);
          if (sizes.empty())
            throw InputError(out,
                             "--tumour",
                             "label " + std::to_string(label) +
                               " is empty; check the inputs");
          const int largest =
            std::max_element(sizes.begin(), sizes.end()) - sizes.begin();
          for (std::size_t v = 0; v < n; ++v)
            if (mine[v] && component[v] != largest)
              labels.labels[v] = unknown;
        }
      fill_unknown(labels);

      write_labelled_image(labels, out, "--out");
      std::cout << out
                << ": cerebrum 1, tumour 2, cerebellum 3, brainstem 4 (voxels:";
      for (const auto &[label, count] : labels.label_counts())
        std::cout << " " << label << ":" << count;
      std::cout << "), brainstem below voxel row z = " << lowest_cerebral
                << std::endl;
    }
  catch (const std::exception &exc)
    {
      std::cerr << "restshape-brain-labels: error: " << one_line_message(exc)
                << std::endl;
      return 1;
    }
  return 0;
}
