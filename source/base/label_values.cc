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
      if (pos != t.size() || t.empty() || value < 0 || value > 65535)
        throw InputError("",
                         parameter,
                         "'" + t +
                           "' is not a label; expected a non-negative "
                           "integer (a physical volume tag of the mesh)");
      return static_cast<Label>(value);
    }
  } // namespace

  LabelValues
  LabelValues::parse(const std::string &text, const std::string &parameter)
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
            result.value_for_all = parse_number(parameter, item);
          }
        else
          {
            const Label label = parse_label(item.substr(0, colon), parameter);
            if (result.per_label.count(label))
              throw InputError("",
                               parameter,
                               "label " + std::to_string(label) +
                                 " is given twice");
            result.per_label[label] =
              parse_number(parameter, item.substr(colon + 1));
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
    if (value_for_all)
      return *value_for_all;
    const auto it = per_label.find(label);
    if (it == per_label.end())
      throw InputError("",
                       parameter,
                       "no value for label " + std::to_string(label) +
                         " of the mesh; expected 'label:value' for every "
                         "label of the mesh, or a single value for all");
    return it->second;
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

  std::vector<FixedLabel>
  parse_fixed_labels(const std::string &text, const std::string &parameter)
  {
    std::vector<FixedLabel> result;
    for (const std::string &item : split_list(text))
      {
        FixedLabel fixed;
        const auto colon = item.find(':');
        fixed.label      = parse_label(item.substr(0, colon), parameter);
        if (colon == std::string::npos)
          fixed.components = {{true, true, true}};
        else
          {
            fixed.components = {{false, false, false}};
            const std::string comps =
              dealii::Utilities::trim(item.substr(colon + 1));
            if (comps.empty())
              throw InputError("",
                               parameter,
                               "'" + item +
                                 "' has no components after ':'; expected "
                                 "a subset of xyz, e.g. '5:xy'");
            for (const char c : comps)
              {
                if (c < 'x' || c > 'z')
                  throw InputError("",
                                   parameter,
                                   "'" + item + "': unknown component '" +
                                     std::string(1, c) +
                                     "'; expected a subset of xyz");
                fixed.components[c - 'x'] = true;
              }
          }
        result.push_back(fixed);
      }
    return result;
  }

  std::set<Label>
  parse_label_set(const std::string &text, const std::string &parameter)
  {
    std::set<Label> labels;
    for (const std::string &item : split_list(text))
      labels.insert(parse_label(item, parameter));
    return labels;
  }

  std::string
  to_string(const std::set<Label> &labels)
  {
    std::string text;
    for (const Label l : labels)
      text += (text.empty() ? "" : ", ") + std::to_string(l);
    return text;
  }
} // namespace RestShape
