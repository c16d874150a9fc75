#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/label_values.h>

#include <cmath>

namespace RestShape
{
  namespace
  {
    std::vector<std::string>
    split_list(const std::string &text)
    {
      std::vector<std::string> items;
      for (const std::string &item :
           dealii::Utilities::split_string_list(text, ','))
        if (!dealii::Utilities::trim(item).empty())
          items.push_back(dealii::Utilities::trim(item));
      return items;
    }

    Label
    parse_label(const std::string &text, const std::string &parameter)
    {
      const std::string t     = dealii::Utilities::trim(text);
      std::size_t       pos   = 0;
      long              value = -1;
      try
        {
          value = std::stol(t, &pos);
        }
      catch (...)
        {
          pos = 0;
        }
      if (pos != t.size() || t.empty() || value < 0 || value > max_label)
        throw InputError("",
                         parameter,
                         "'" + t +
                           "' is not a label; expected a non-negative "
                           "integer (a physical volume tag of the mesh), "
                           "a range such as '1-90' or a name of a label "
                           "($PhysicalNames of the mesh, Mesh/Label names)");
      return static_cast<Label>(value);
    }

    /// "7" -> [7, 7]; "1-90" -> [1, 90].
    std::pair<Label, Label>
    parse_label_range(const std::string &text, const std::string &parameter)
    {
      const std::string t    = dealii::Utilities::trim(text);
      const auto        dash = t.find('-', 1);
      if (dash == std::string::npos)
        {
          const Label l = parse_label(t, parameter);
          return {l, l};
        }
      const Label first = parse_label(t.substr(0, dash), parameter);
      const Label last  = parse_label(t.substr(dash + 1), parameter);
      if (last < first)
        throw InputError("",
                         parameter,
                         "'" + t + "': a range must run upwards, e.g. '1-90'");
      return {first, last};
    }

    /// A whole number from 0 to max_label, or nothing.
    std::optional<Label>
    whole_label(const std::string &text)
    {
      constexpr std::size_t max_digits = 10;
      if (text.empty() || text.size() > max_digits ||
          text.find_first_not_of("0123456789") != std::string::npos ||
          std::stol(text) > max_label)
        return std::nullopt;
      return Label(std::stol(text));
    }

    /// The label part of a list entry ("1-90" of "1-90:1500").
    std::string
    key_of(const std::string &item)
    {
      return dealii::Utilities::trim(item.substr(0, item.find(':')));
    }
  } // namespace

  std::optional<std::pair<Label, Label>>
  label_range(const std::string &text)
  {
    const std::string t = dealii::Utilities::trim(text);
    if (const auto l = whole_label(t))
      return std::make_pair(*l, *l);
    const auto dash = t.find('-', 1);
    if (dash == std::string::npos)
      return std::nullopt;
    const auto first = whole_label(t.substr(0, dash));
    const auto last  = whole_label(t.substr(dash + 1));
    if (!first || !last || *last < *first)
      return std::nullopt;
    return std::make_pair(*first, *last);
  }

  LabelValues
  LabelValues::parse(const std::string &text, const std::string &parameter)
  {
    return parse(text, parameter, [&](const std::string &value) {
      return parse_number(parameter, value);
    });
  }

  LabelValues
  LabelValues::parse(const std::string &text,
                     const std::string &parameter,
                     const std::function<double(const std::string &)> &value)
  {
    LabelValues result;
    result.parameter                     = parameter;
    const std::vector<std::string> items = split_list(text);
    if (items.empty())
      throw InputError("",
                       parameter,
                       "no value given; expected one value for all labels "
                       "or a list 'label:value, label:value'");
    for (const std::string &item : items)
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          {
            if (items.size() != 1)
              throw InputError("",
                               parameter,
                               "'" + item +
                                 "' has no label; in a list every entry "
                                 "must be 'label:value'");
            result.value_for_all = value(item);
          }
        else if (key_of(item) == "*")
          {
            if (result.value_for_all)
              throw InputError("", parameter, "the default '*' is given twice");
            result.value_for_all = value(item.substr(colon + 1));
          }
        else
          {
            const auto [first, last] =
              parse_label_range(item.substr(0, colon), parameter);
            const double v = value(item.substr(colon + 1));
            for (long l = first; l <= long(last); ++l)
              if (!result.per_label.emplace(Label(l), v).second)
                throw InputError("",
                                 parameter,
                                 "label " + std::to_string(l) +
                                   " is given twice");
          }
      }
    return result;
  }

  bool
  LabelValues::has(const Label label) const
  {
    return value_for_all.has_value() || per_label.count(label) > 0;
  }

  double
  LabelValues::operator()(const Label label) const
  {
    const auto it = per_label.find(label);
    if (it != per_label.end())
      return it->second;
    if (value_for_all)
      return *value_for_all;
    throw InputError("",
                     parameter,
                     "no value for label " + std::to_string(label) +
                       " of the mesh; expected 'label:value' for every "
                       "label of the mesh, a default '*:value', or a "
                       "single value for all");
  }

  std::vector<std::pair<Label, double>>
  LabelValues::listed() const
  {
    std::vector<std::pair<Label, double>> values(per_label.begin(),
                                                 per_label.end());
    if (value_for_all)
      values.emplace_back(dealii::numbers::invalid_material_id, *value_for_all);
    return values;
  }

  std::array<bool, 3>
  parse_components(const std::string &item,
                   const std::string &components,
                   const std::string &parameter,
                   const std::string &example)
  {
    std::array<bool, 3> result{{false, false, false}};
    if (components.empty())
      throw InputError("",
                       parameter,
                       "'" + item +
                         "' has no components after ':'; expected a subset "
                         "of xyz, e.g. '" +
                         example + "'");
    for (const char c : components)
      {
        if (c < 'x' || c > 'z')
          throw InputError("",
                           parameter,
                           "'" + item + "': unknown component '" +
                             std::string(1, c) + "'; expected a subset of xyz");
        result[c - 'x'] = true;
      }
    return result;
  }

  std::vector<FixedLabel>
  parse_fixed_labels(const std::string &text, const std::string &parameter)
  {
    std::vector<FixedLabel> result;
    for (const std::string &item : split_list(text))
      {
        FixedLabel fixed;
        const auto colon         = item.find(':');
        const auto [first, last] = parse_label_range(key_of(item), parameter);
        if (colon == std::string::npos)
          fixed.components = {{true, true, true}};
        else
          fixed.components =
            parse_components(item,
                             dealii::Utilities::trim(item.substr(colon + 1)),
                             parameter,
                             "5:xy");
        for (long l = first; l <= long(last); ++l)
          {
            fixed.label = Label(l);
            result.push_back(fixed);
          }
      }
    return result;
  }

  std::set<Label>
  parse_label_set(const std::string &text, const std::string &parameter)
  {
    std::set<Label> labels;
    for (const std::string &item : split_list(text))
      {
        const auto [first, last] = parse_label_range(item, parameter);
        for (long l = first; l <= long(last); ++l)
          labels.insert(Label(l));
      }
    return labels;
  }

  void
  check_labels_exist(const LabelList &list, const std::set<Label> &labels)
  {
    for (const std::string &item : split_list(list.text))
      {
        const std::string key = key_of(item);
        // A single value for all labels, or the default.
        if (key == "*" || (list.values && item.find(':') == std::string::npos))
          continue;
        const auto [first, last] = parse_label_range(key, list.parameter);
        if (labels.lower_bound(first) == labels.upper_bound(last))
          throw InputError("",
                           list.parameter,
                           (first == last ? "label " : "no label in ") + key +
                             (first == last ? " is not a label" :
                                              " is a label") +
                             " of the mesh (labels: " + to_string(labels) +
                             ")");
      }
  }

  std::string
  to_string(const std::set<Label> &labels)
  {
    // Long lists (an atlas has hundreds of labels) are shortened.
    constexpr unsigned int               max_runs = 12;
    std::vector<std::pair<Label, Label>> runs;
    for (const Label l : labels)
      if (!runs.empty() && runs.back().second + 1 == l)
        runs.back().second = l;
      else
        runs.emplace_back(l, l);
    std::string text;
    for (unsigned int i = 0; i < runs.size(); ++i)
      {
        if (i == max_runs - 2 && runs.size() > max_runs)
          {
            text += ", ... (" + std::to_string(labels.size()) + " labels), ";
            i = runs.size() - 1;
          }
        else if (!text.empty())
          text += ", ";
        const auto [first, last] = runs[i];
        text += std::to_string(first) +
                (last == first     ? "" :
                 last == first + 1 ? ", " + std::to_string(last) :
                                     "-" + std::to_string(last));
      }
    return text;
  }
} // namespace RestShape
