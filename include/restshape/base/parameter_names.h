// The names a ParameterHandler declares, to tell a user who misspelled one
// which names are near: for scene files (with their include lines) and for
// --set alike.
#ifndef restshape_parameter_names_h
#define restshape_parameter_names_h

#include <deal.II/base/parameter_handler.h>

#include <set>
#include <string>
#include <vector>

namespace RestShape
{
  /**
   * The known names nearest to @p name (at most three, within a third of
   * its length in edit distance; case, blanks, apostrophes and underscores
   * ignored; of paths "A/B" only the last parts are compared).
   */
  std::vector<std::string>
  nearest_names(const std::string &name, const std::set<std::string> &known);

  /// "; did you mean 'a', 'b'?" (empty for no names).
  std::string
  did_you_mean(const std::vector<std::string> &names);

  /**
   * Every subsection and entry of a ParameterHandler as a path
   * ("Materials/Young's modulus"). Unknown names get InputErrors that name
   * the nearest known ones (edit distance, case and spacing ignored).
   */
  class ParameterNames
  {
  public:
    explicit ParameterNames(const dealii::ParameterHandler &prm);

    /**
     * Read @p file (and the files it includes) line by line as deal.II
     * does and throw InputError (file, "line N") at the first subsection
     * or entry that is not declared, with the nearest known names. Does
     * nothing if every name is known.
     */
    void
    check_file(const std::string &file) const;

    /// Throw InputError ("--set", path) if @p path ("Sub/Entry") is not a
    /// declared entry, with the nearest known ones.
    void
    check_entry(const std::string &path) const;

    /// Throw InputError if @p path is not a top-level subsection.
    void
    check_top_subsection(const std::string &path) const;

  private:
    /// "unknown subsection 'X'; nearest: 'A', 'B'" (or entry).
    std::string
    unknown_text(const std::string           &kind,
                 const std::string           &path,
                 const std::set<std::string> &known) const;

    std::set<std::string> subsections, entries;
  };
} // namespace RestShape

#endif
