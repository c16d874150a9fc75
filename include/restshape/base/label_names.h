// Names of labels ("cerebrum" for label 1): read from "label name" tables
// (the .nii.txt files next to atlases), carried by gmsh meshes as
// $PhysicalNames, and accepted wherever a scene lists labels.
#ifndef restshape_label_names_h
#define restshape_label_names_h

#include <restshape/base/label_values.h>

#include <iosfwd>
#include <map>
#include <optional>
#include <string>

namespace RestShape
{
  /**
   * A name per label, one label per name. A name is one word with at least
   * one letter and none of the characters a label list uses (blank , : * "
   * #), so that "cerebrum:1500" and "3rd_ventricle" are unambiguous.
   */
  class LabelNames
  {
  public:
    /// Name @p label; throws InputError naming @p file and @p option for a
    /// malformed name, a name of another label, or a second name.
    void
    add(const Label        label,
        const std::string &name,
        const std::string &file,
        const std::string &option);

    std::optional<Label>
    find(const std::string &name) const;

    /// The name of @p label, or "" if it has none.
    std::string
    name(const Label label) const;

    bool
    empty() const;

    const std::map<Label, std::string> &
    by_label() const;

    /// "cerebrum (1), cerebellum (3)" for messages, shortened if long.
    std::string
    known_text() const;

    /// Whether @p name can name a label (see the class).
    static bool
    is_valid_name(const std::string &name);

  private:
    std::map<Label, std::string> names;
    std::map<std::string, Label> labels;
  };

  /**
   * Read a "label name [anything]" table, one label per line (the .nii.txt
   * name tables of mricron's atlases; tabs or blanks, CR/LF line ends, '#'
   * comments and blank lines skipped). Errors name @p file, @p option and
   * the line.
   */
  LabelNames
  read_label_names(const std::string &file, const std::string &option);

  /// Write the table as read_label_names() reads it.
  void
  write_label_names(const LabelNames &names, std::ostream &out);

  /**
   * The label list @p text of @p parameter with names replaced by their
   * labels: "cerebrum:1500, *:1000" -> "1:1500, *:1000". Labels, ranges,
   * the default '*' and a lone value of a value list (@p values) are kept.
   * A word that is neither a label nor a name in @p names is an InputError
   * that lists the known names (when there are any).
   */
  std::string
  replace_label_names(const std::string &text,
                      const std::string &parameter,
                      const LabelNames  &names,
                      const bool         values);
} // namespace RestShape

#endif
