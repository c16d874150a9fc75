// Parsing of per-label lists such as "1:1500, 2:10000", "1-90:1500, *:2000"
// or "3, 5:xy".
#ifndef restshape_label_values_h
#define restshape_label_values_h

#include <deal.II/base/types.h>

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace RestShape
{
  using Label = dealii::types::material_id;
  /// The largest label: a gmsh physical tag is a signed int.
  constexpr long max_label = 2147483647;

  /**
   * A value per label: either "value" (the same for every label) or a list
   * "label:value, label:value" whose labels may be ranges ("1-90:1500") and
   * may end with a default for every other label ("*:1500"). Parse errors
   * throw InputError naming @p parameter.
   */
  class LabelValues
  {
  public:
    static LabelValues
    parse(const std::string &text, const std::string &parameter);
    /// The same with values that are not numbers: @p value turns each
    /// value's text into a number (or throws InputError).
    static LabelValues
    parse(const std::string                                &text,
          const std::string                                &parameter,
          const std::function<double(const std::string &)> &value);

    /// The value of @p label; throws InputError if there is none.
    double
    operator()(const Label label) const;

    bool
    has(const Label label) const;

    /// All values given (for range checks).
    std::vector<std::pair<Label, double>>
    listed() const;

    /// The single value, or the default ("*:value").
    std::optional<double>   value_for_all;
    std::map<Label, double> per_label;
    std::string             parameter;
  };

  /// A label with the displacement components it fixes ("5:xy").
  struct FixedLabel
  {
    Label               label;
    std::array<bool, 3> components;
  };

  /// The displacement components named after the ':' of @p item of
  /// @p parameter ("xz" -> x and z); @p example shows a whole item in the
  /// error for an empty list.
  std::array<bool, 3>
  parse_components(const std::string &item,
                   const std::string &components,
                   const std::string &parameter,
                   const std::string &example);

  /// Parse "3, 5:xy, 7-9" (empty allowed).
  std::vector<FixedLabel>
  parse_fixed_labels(const std::string &text, const std::string &parameter);

  /// "7" -> [7, 7], "1-90" -> [1, 90]; nothing if @p text is not a label
  /// (a whole number from 0 to max_label) or an upward range of them.
  std::optional<std::pair<Label, Label>>
  label_range(const std::string &text);

  /// Parse "1, 2, 7-9" (empty allowed).
  std::set<Label>
  parse_label_set(const std::string &text, const std::string &parameter);

  /// A label list as written in a parameter, for the check against the mesh.
  struct LabelList
  {
    std::string parameter; // "Materials/Young's modulus"
    std::string text;      // "1-90:1500, *:2000"
    /// A LabelValues list: a lone entry without ':' is a value for all.
    bool values = false;
  };

  /**
   * Check the labels of a (parsed, valid) list against the labels of the
   * mesh: a single label must be one of them, a range must hold at least
   * one; throws InputError naming the parameter, the entry and the mesh's
   * labels otherwise.
   */
  void
  check_labels_exist(const LabelList &list, const std::set<Label> &labels);

  /// "1-4, 7" for messages: runs of consecutive labels as ranges.
  std::string
  to_string(const std::set<Label> &labels);
} // namespace RestShape

#endif
