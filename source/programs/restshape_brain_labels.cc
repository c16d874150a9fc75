// restshape-brain-labels: the labelled brain image of the paper's scene,
// built from Debian's mricron-data (Colin27 on the MNI grid), optionally
// with the tissues of a second atlas laid over it through a label map.
//
//   restshape-brain-labels --brain ch2bet.nii.gz --atlas aal.nii.gz
//       --out LABELS.nii.gz [--tumour X,Y,Z --tumour-radius MM]
//       [--brainstem-half-width MM]
//       [--overlay ATLAS.nii.gz --overlay-map MAP.txt
//        [--overlay-names ATLAS.nii.txt]] [--names-out NAMES.txt]
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
//  - overlay: brain voxels whose nearest --overlay voxel (any grid, matched
//    by world coordinates) has a label that --overlay-map lists take its
//    tissue label (the map's lines "ATLAS_LABELS TISSUE NAME", as for
//    restshape-mesh --label-map; atlas names with --overlay-names); other
//    voxels keep theirs;
//  - tumour: the brain voxels within --tumour-radius mm of --tumour (MNI mm);
//  - finally every label keeps only its largest connected piece; the other
//    pieces are given to their neighbours, so that each region is one solid.
// --names-out writes the labels' names as a 'label name' table, for
// restshape-mesh --label-names.
#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/interruption.h>
#include <restshape/base/label_names.h>
#include <restshape/base/version.h>
#include <restshape/mesher/image_morphology.h>
#include <restshape/mesher/label_map.h>
#include <restshape/mesher/labelled_image.h>

#include <algorithm>
#include <deque>
#include <fstream>
#include <iostream>
#include <optional>

namespace
{
  /// --help: the usage comment at the top of this file.
  const char *const usage =
    "restshape-brain-labels: the labelled brain image of the paper's scene,\n"
    "built from Debian's mricron-data (Colin27 on the MNI grid), optionally\n"
    "with the tissues of a second atlas laid over it through a label map.\n"
    "\n"
    "  restshape-brain-labels --brain ch2bet.nii.gz --atlas aal.nii.gz\n"
    "      --out LABELS.nii.gz [--tumour X,Y,Z --tumour-radius MM]\n"
    "      [--brainstem-half-width MM]\n"
    "      [--overlay ATLAS.nii.gz --overlay-map MAP.txt\n"
    "       [--overlay-names ATLAS.nii.txt]] [--names-out NAMES.txt]\n"
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
    " - overlay: brain voxels whose nearest --overlay voxel (any grid, matched\n"
    "   by world coordinates) has a label that --overlay-map lists take its\n"
    "   tissue label (the map's lines 'ATLAS_LABELS TISSUE NAME', as for\n"
    "   restshape-mesh --label-map; atlas names with --overlay-names); other\n"
    "   voxels keep theirs;\n"
    " - tumour: the brain voxels within --tumour-radius mm of --tumour (MNI mm);\n"
    " - finally every label keeps only its largest connected piece; the other\n"
    "   pieces are given to their neighbours, so that each region is one solid.\n"
    "--names-out writes the labels' names as a 'label name' table, for\n"
    "restshape-mesh --label-names.\n";
} // namespace

using namespace RestShape;

namespace
{
  constexpr ImageLabel cerebrum = 1, tumour = 2, cerebellum = 3, brainstem = 4;
  /// A brain voxel whose label is not decided yet.
  constexpr ImageLabel unknown = max_image_label;
  /// AAL's cerebral and cerebellar indices.
  constexpr ImageLabel aal_cerebral_last = 90, aal_cerebellar_last = 116;

  struct Settings
  {
    std::string           brain_file, atlas_file, out, names_out;
    std::string           overlay_file, overlay_map_file, overlay_names_file;
    std::array<double, 3> centre;
    double                radius = 12, half_width = 16;
  };

  Settings
  read_settings(const ToolOptions &cl)
  {
    Settings s;
    s.brain_file = cl.required("--brain", "a brain mask, e.g. ch2bet.nii.gz");
    s.atlas_file = cl.required("--atlas", "a labelled atlas, e.g. aal.nii.gz");
    s.out        = cl.required("--out", "the output image, e.g. LABELS.nii.gz");
    s.centre     = cl.triple("--tumour", {{-32, 28, 28}});
    s.radius     = cl.positive("--tumour-radius", 12);
    s.half_width = cl.positive("--brainstem-half-width", 16);
    s.names_out  = cl.text("--names-out");
    s.overlay_file       = cl.text("--overlay");
    s.overlay_map_file   = cl.text("--overlay-map");
    s.overlay_names_file = cl.text("--overlay-names");
    if (!s.overlay_file.empty() && s.overlay_map_file.empty())
      throw InputError(s.overlay_file,
                       "--overlay-map",
                       "missing; expected a label map for --overlay (lines "
                       "'ATLAS_LABELS TISSUE NAME')");
    for (const char *option : {"--overlay-map", "--overlay-names"})
      if (s.overlay_file.empty() && cl.given(option))
        throw InputError(cl.text(option),
                         option,
                         "given without --overlay; expected an atlas to lay "
                         "over the brain");
    return s;
  }

  /// The voxels of the largest face-connected component of @p mask.
  std::vector<bool>
  largest_component(const LabelledImage &image, const std::vector<bool> &mask)
  {
    const auto [component, sizes] = face_connected_components(image, mask);
    const int largest =
      std::max_element(sizes.begin(), sizes.end()) - sizes.begin();
    std::vector<bool> in(mask.size());
    for (std::size_t v = 0; v < mask.size(); ++v)
      in[v] = component[v] == largest;
    return in;
  }

  /// The brain: the largest component of the mask, its cavities filled.
  std::vector<bool>
  brain_region(const LabelledImage &brain)
  {
    const std::size_t n = brain.labels.size();
    std::vector<bool> in(n);
    for (std::size_t v = 0; v < n; ++v)
      in[v] = brain.labels[v] != 0;
    in = largest_component(brain, in);
    std::vector<bool> out_of_brain(n);
    for (std::size_t v = 0; v < n; ++v)
      out_of_brain[v] = !in[v];
    const auto [component, sizes] =
      face_connected_components(brain, out_of_brain);
    const int outside = component[0]; // the corner voxel is background
    for (std::size_t v = 0; v < n; ++v)
      if (!in[v] && component[v] != outside)
        in[v] = true;
    return in;
  }

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

  /// Cerebrum, cerebellum and brainstem from AAL and the brain's shape;
  /// returns the row below which the brainstem lies.
  unsigned int
  anatomy(LabelledImage           &labels,
          const std::vector<bool> &in,
          const LabelledImage     &atlas,
          const double             half_width)
  {
    const auto  &size            = labels.size;
    unsigned int lowest_cerebral = size[2];
    for (std::size_t v = 0; v < in.size(); ++v)
      if (in[v] && atlas.labels[v] >= 1 && atlas.labels[v] <= aal_cerebral_last)
        lowest_cerebral =
          std::min<unsigned int>(lowest_cerebral,
                                 v / (std::size_t(size[0]) * size[1]));
    for (unsigned int k = 0; k < size[2]; ++k)
      for (unsigned int j = 0; j < size[1]; ++j)
        for (unsigned int i = 0; i < size[0]; ++i)
          {
            const std::size_t v = labels.index(i, j, k);
            const ImageLabel  a = atlas.labels[v];
            ImageLabel       &l = labels.labels[v];
            if (!in[v])
              l = 0;
            else if (a > aal_cerebral_last && a <= aal_cerebellar_last)
              l = cerebellum;
            else if (a >= 1 && a <= aal_cerebral_last)
              l = cerebrum;
            else if (k < lowest_cerebral &&
                     std::abs(labels.position(i, j, k)[0]) < half_width)
              l = brainstem;
            else
              l = unknown;
          }
    fill_unknown(labels);
    return lowest_cerebral;
  }

  /// Lay the tissues of --overlay over the brain; returns the voxels that
  /// changed label.
  std::size_t
  lay_overlay(LabelledImage &labels, const Settings &s, LabelNames &names)
  {
    const LabelNames atlas_names =
      s.overlay_names_file.empty() ?
        LabelNames() :
        read_label_names(s.overlay_names_file, "--overlay-names");
    const LabelMap map = LabelMap::read(s.overlay_map_file,
                                        "--overlay-map",
                                        atlas_names,
                                        "--overlay-names");
    for (const auto &[label, name] : map.tissue_names().by_label())
      names.add(label, name, s.overlay_map_file, "--overlay-map");
    const LabelledImage overlay =
      read_labelled_image(s.overlay_file, "--overlay");
    std::size_t changed = 0;
    for (unsigned int k = 0; k < labels.size[2]; ++k)
      for (unsigned int j = 0; j < labels.size[1]; ++j)
        for (unsigned int i = 0; i < labels.size[0]; ++i)
          {
            ImageLabel &l = labels.labels[labels.index(i, j, k)];
            if (l == 0)
              continue;
            const ImageLabel a = overlay.label_at(labels.position(i, j, k));
            const std::optional<ImageLabel> tissue = map(a);
            if (a == 0 || !tissue || *tissue == 0 || *tissue == l)
              continue;
            l = *tissue;
            ++changed;
          }
    if (changed == 0)
      throw InputError(s.overlay_file,
                       "--overlay",
                       "no brain voxel lies on a label that --overlay-map "
                       "lists; expected an atlas in the brain's world "
                       "coordinates");
    return changed;
  }

  void
  add_tumour(LabelledImage &labels, const Settings &s)
  {
    const dealii::Point<3> centre(s.centre[0], s.centre[1], s.centre[2]);
    for (unsigned int k = 0; k < labels.size[2]; ++k)
      for (unsigned int j = 0; j < labels.size[1]; ++j)
        for (unsigned int i = 0; i < labels.size[0]; ++i)
          {
            ImageLabel &l = labels.labels[labels.index(i, j, k)];
            if (l != 0 && labels.position(i, j, k).distance(centre) <= s.radius)
              l = tumour;
          }
  }

  /// Every label keeps its largest connected piece; the rest goes to the
  /// neighbours.
  void
  keep_largest_pieces(LabelledImage &labels, const Settings &s)
  {
    const std::size_t n = labels.labels.size();
    for (const auto &[label, count] : labels.label_counts())
      {
        std::vector<bool> mine(n);
        for (std::size_t v = 0; v < n; ++v)
          mine[v] = labels.labels[v] == label;
        const std::vector<bool> kept = largest_component(labels, mine);
        for (std::size_t v = 0; v < n; ++v)
          if (mine[v] && !kept[v])
            labels.labels[v] = unknown;
      }
    fill_unknown(labels);
    const auto counts = labels.label_counts();
    for (const ImageLabel label : {cerebrum, tumour, cerebellum, brainstem})
      if (counts.count(label) == 0)
        throw InputError(s.out,
                         "--tumour",
                         "label " + std::to_string(label) +
                           " is empty; check the inputs");
  }

  void
  write_names(const LabelNames    &names,
              const LabelledImage &labels,
              const std::string   &file)
  {
    LabelNames present;
    for (const auto &[label, count] : labels.label_counts())
      if (!names.name(label).empty())
        present.add(label, names.name(label), file, "--names-out");
    std::ofstream out(file);
    write_label_names(present, out);
    if (!out)
      throw InputError(file, "--names-out", "cannot write the file");
  }
} // namespace

int
main(int argc, char **argv)
{
  RestShape::install_interrupt_handlers();
  try
    {
      const ToolOptions cl(argc,
                           argv,
                           {"--brain",
                            "--atlas",
                            "--out",
                            "--tumour",
                            "--tumour-radius",
                            "--brainstem-half-width",
                            "--overlay",
                            "--overlay-map",
                            "--overlay-names",
                            "--names-out"});
      if (cl.version())
        {
          std::cout << version_text("restshape-brain-labels") << std::endl;
          return 0;
        }
      if (cl.help())
        {
          std::cout << usage;
          return 0;
        }
      const Settings      s     = read_settings(cl);
      const LabelledImage brain = read_labelled_image(s.brain_file, "--brain");
      const LabelledImage atlas = read_labelled_image(s.atlas_file, "--atlas");
      if (brain.size != atlas.size ||
          (brain.index_to_mm - atlas.index_to_mm).norm() > 1e-6 ||
          (brain.offset - atlas.offset).norm() > 1e-6)
        throw InputError(
          s.atlas_file,
          "--atlas",
          "not on the grid of --brain; expected both on the same voxel grid");

      LabelNames names;
      for (const auto &[label, name] :
           std::vector<std::pair<ImageLabel, std::string>>{
             {cerebrum, "cerebrum"},
             {tumour, "tumour"},
             {cerebellum, "cerebellum"},
             {brainstem, "brainstem"}})
        names.add(label, name, s.out, "--out");
      LabelledImage      labels = brain;
      const unsigned int lowest_cerebral =
        anatomy(labels, brain_region(brain), atlas, s.half_width);
      const std::size_t n_overlaid =
        s.overlay_file.empty() ? 0 : lay_overlay(labels, s, names);
      add_tumour(labels, s);
      keep_largest_pieces(labels, s);

      write_labelled_image(labels, s.out, "--out");
      if (!s.names_out.empty())
        write_names(names, labels, s.names_out);
      std::cout << s.out << ": " << names.known_text() << " (voxels:";
      for (const auto &[label, count] : labels.label_counts())
        std::cout << " " << label << ":" << count;
      std::cout << "), brainstem below voxel row z = " << lowest_cerebral;
      if (!s.overlay_file.empty())
        std::cout << ", " << n_overlaid << " voxels from " << s.overlay_file;
      std::cout << std::endl;
    }
  catch (const std::exception &exc)
    {
      std::cerr << "restshape-brain-labels: error: " << one_line_message(exc)
                << std::endl;
      return 1;
    }
  return 0;
}
