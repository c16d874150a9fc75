// A labelled 3d image (NIfTI-1 or NIfTI-2, through libnifti): integer labels
// on a voxel grid, with the voxel-to-millimetre map of its header.
#ifndef restshape_labelled_image_h
#define restshape_labelled_image_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/base/label_values.h>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace RestShape
{
  /// A voxel's label: 0 background, up to max_label (the largest label a
  /// mesh and a scene can carry).
  using ImageLabel                     = std::uint32_t;
  constexpr ImageLabel max_image_label = max_label;

  struct LabelledImage
  {
    /// Voxels along i, j, k.
    std::array<unsigned int, 3> size{{0, 0, 0}};
    /// The voxel-to-millimetre map: x_mm = index_to_mm * (i, j, k) + offset.
    /// Taken from the sform, else the qform, else the voxel sizes.
    dealii::Tensor<2, 3> index_to_mm;
    dealii::Tensor<1, 3> offset;
    /// NIfTI xform code of that map (1 scanner, 2 aligned, 3 Talairach, 4 MNI).
    int xform_code = 1;
    /// Labels (0 = background), i fastest, as stored in the file.
    std::vector<ImageLabel> labels;

    /// The largest label.
    ImageLabel
    max_label() const;

    /// Bytes of the smallest unsigned word that holds every label (1, 2
    /// or 4).
    unsigned int
    label_bytes() const;

    /// Store the labels in @p data as unsigned words of label_bytes().
    void
    store_labels(void *data) const;

    std::size_t
    index(const unsigned int i,
          const unsigned int j,
          const unsigned int k) const
    {
      return i + std::size_t(size[0]) * (j + std::size_t(size[1]) * k);
    }

    /// Voxel edge lengths (mm): the lengths of the columns of index_to_mm.
    std::array<double, 3>
    spacing() const;

    /// Position (mm) of the centre of voxel (i, j, k).
    dealii::Point<3>
    position(const double i, const double j, const double k) const;

    /// The label of the voxel whose centre is nearest to @p x (mm, world
    /// coordinates); 0 outside the grid.
    ImageLabel
    label_at(const dealii::Point<3> &x) const;

    /// Number of voxels of every non-zero label.
    std::map<unsigned int, std::size_t>
    label_counts() const;
  };

  /**
   * Read a labelled image (.nii or .nii.gz). Integer data types up to 32
   * bits, and floating-point data holding whole numbers, are accepted;
   * labels must lie in 0..max_image_label. Throws InputError naming @p file
   * and @p parameter for a missing or unreadable file, a non-3d image, a
   * negative or fractional or too large label (naming the voxel) or an
   * image without any non-zero label.
   */
  LabelledImage
  read_labelled_image(const std::string &file, const std::string &parameter);

  /// Write @p image as NIfTI-1 (.nii or .nii.gz) with its map as sform, in
  /// the smallest unsigned type that holds its labels (uint8, uint16, ...).
  /// Written under a temporary name and renamed into place.
  void
  write_labelled_image(const LabelledImage &image,
                       const std::string   &file,
                       const std::string   &parameter);
} // namespace RestShape

#endif
