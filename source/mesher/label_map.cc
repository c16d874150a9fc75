#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/input_file.h>
#include <restshape/mesher/label_map.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// "7", "1-90" or an atlas name -> [first, last]; else nothing.
    std::optional<std::pair<Label, Label>>
    atlas_range(const std::string &text, const LabelNames &atlas_names)
    {
      if (const auto named = atlas_names.find(text))
        return std::make_pair(*named, *named);
      return label_range(text);
    }
  } // namespace

  LabelMap
  LabelMap::read(const std::string &file,
                 const std::string &option,
                 const LabelNames  &atlas_names,
                 const std::string &names_option)
  {
    std::ifstream in =
      open_input(file, option, "lines 'ATLAS_LABELS TISSUE_LABEL [NAME]'");
    LabelMap     map;
    std::string  line;
    unsigned int line_number = 0;
    while (std::getline(in, line))
      {
        ++line_number;
        const std::string  at = "line " + std::to_string(line_number) + ": ";
        std::istringstream words(line.substr(0, line.find('#')));
        std::string        sources, tissue_text, name, extra;
        if (!(words >> sources))
          continue;
        words >> tissue_text >> name >> extra;
        const auto tissue_range = label_range(tissue_text);
        const auto tissue =
          tissue_range && tissue_range->first == tissue_range->second ?
            std::optional<Label>(tissue_range->first) :
            std::nullopt;
        if (!tissue || !extra.empty())
          throw InputError(file,
                           option,
                           at +
                             "expected 'ATLAS_LABELS TISSUE_LABEL [NAME]' "
                             "with a tissue label from 0 to " +
                             std::to_string(max_label) + ", got '" +
                             dealii::Utilities::trim(line) + "'");
        if (!name.empty())
          {
            if (*tissue == 0)
              throw InputError(file,
                               option,
                               at + "tissue label 0 is the background and "
                                    "takes no name");
            try
              {
                map.names.add(*tissue, name, file, option);
              }
            catch (const InputError &e)
              {
                throw InputError(file, option, at + e.message);
              }
          }
        for (const std::string &source :
             dealii::Utilities::split_string_list(sources, ','))
          {
            const auto range = atlas_range(source, atlas_names);
            if (!range)
              throw InputError(
                file,
                option,
                at + "'" + source +
                  "' is not an atlas label; expected a label, a range "
                  "such as '1-90'" +
                  (atlas_names.empty() ? " (names need " + names_option + ")" :
                                         " or a name of " + names_option));
            map.ranges.push_back(
              {range->first, range->second, *tissue, line_number});
          }
      }
    if (map.ranges.empty())
      throw InputError(file, option, "the map lists no atlas label");
    std::sort(map.ranges.begin(),
              map.ranges.end(),
              [](const Range &a, const Range &b) { return a.first < b.first; });
    for (unsigned int i = 1; i < map.ranges.size(); ++i)
      if (map.ranges[i].first <= map.ranges[i - 1].last)
        throw InputError(file,
                         option,
                         "atlas label " + std::to_string(map.ranges[i].first) +
                           " is mapped on lines " +
                           std::to_string(std::min(map.ranges[i - 1].line,
                                                   map.ranges[i].line)) +
                           " and " +
                           std::to_string(std::max(map.ranges[i - 1].line,
                                                   map.ranges[i].line)) +
                           "; expected each atlas label once");
    return map;
  }

  std::optional<ImageLabel>
  LabelMap::operator()(const ImageLabel atlas_label) const
  {
    auto it = std::upper_bound(ranges.begin(),
                               ranges.end(),
                               atlas_label,
                               [](const ImageLabel l, const Range &r) {
                                 return l < r.first;
                               });
    if (it == ranges.begin() || (--it)->last < atlas_label)
      return std::nullopt;
    return it->tissue;
  }

  const LabelNames &
  LabelMap::tissue_names() const
  {
    return names;
  }

  std::size_t
  apply_label_map(LabelledImage       &image,
                  const LabelMap      &map,
                  const UnlistedLabels unlisted,
                  const std::string   &file,
                  const std::string   &option)
  {
    // Once per label, not per voxel.
    std::map<ImageLabel, ImageLabel> tissue_of;
    std::set<Label>                  missing;
    for (const auto &[label, count] : image.label_counts())
      {
        const auto tissue = map(label);
        if (!tissue)
          missing.insert(label);
        tissue_of[label] = tissue.value_or(0);
      }
    if (!missing.empty() && unlisted == UnlistedLabels::error)
      throw InputError(file,
                       option,
                       "the image's labels " + to_string(missing) +
                         " are not in the map; expected every label of "
                         "the image mapped (or --unlisted-labels "
                         "background)");
    std::size_t n_dropped = 0;
    for (ImageLabel &l : image.labels)
      if (l != 0)
        {
          l = tissue_of[l];
          n_dropped += (l == 0);
        }
    return n_dropped;
  }
} // namespace RestShape
