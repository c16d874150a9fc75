// A label map: atlas labels merged into tissue labels with names, read from
// a small text table (restshape-mesh --label-map).
#ifndef restshape_mesher_label_map_h
#define restshape_mesher_label_map_h

#include <restshape/base/label_names.h>
#include <restshape/mesher/labelled_image.h>

#include <optional>
#include <string>
#include <vector>

namespace RestShape
{
  /**
   * Lines "ATLAS_LABELS TISSUE_LABEL [NAME]", e.g.
   *
   *   # atlas labels -> tissue label  name
   *   1-90            1  cerebrum
   *   91-116          3  cerebellum
   *   120,122         0               (background: left out)
   *
   * ATLAS_LABELS is a comma-separated list (no blanks) of labels, ranges
   * "a-b" and, given a name table of the atlas, atlas names. Tissue label 0
   * is the background. A tissue keeps one name; an atlas label may appear
   * only once.
   */
  class LabelMap
  {
  public:
    /// Read @p file; errors name it, @p option and the line, and
    /// @p names_option as where the atlas names come from.
    static LabelMap
    read(const std::string &file,
         const std::string &option,
         const LabelNames  &atlas_names,
         const std::string &names_option = "--label-names");

    /// The tissue label of @p atlas_label, if listed.
    std::optional<ImageLabel>
    operator()(const ImageLabel atlas_label) const;

    /// The names of the tissue labels.
    const LabelNames &
    tissue_names() const;

  private:
    struct Range
    {
      ImageLabel   first, last, tissue;
      unsigned int line;
    };
    std::vector<Range> ranges; // sorted by first
    LabelNames         names;
  };

  /// What labels of an image that a label map does not list become.
  enum class UnlistedLabels
  {
    error,
    background
  };

  /**
   * Replace every voxel's label of @p image by its tissue label. Unlisted
   * labels become background, or (UnlistedLabels::error) are one
   * InputError naming @p file and @p option that lists them. Returns the
   * number of voxels that became background.
   */
  std::size_t
  apply_label_map(LabelledImage       &image,
                  const LabelMap      &map,
                  const UnlistedLabels unlisted,
                  const std::string   &file,
                  const std::string   &option);
} // namespace RestShape

#endif
