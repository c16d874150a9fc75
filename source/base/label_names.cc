#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/input_file.h>
#include <restshape/base/label_names.h>
#include <restshape/base/parameter_names.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// Characters a name cannot hold: blanks and a label list's syntax.
    const std::string forbidden = " \t\r\n,:*\"#";

  } // namespace

  bool
  LabelNames::is_valid_name(const std::string &name)
  {
    return !name.empty() &&
           name.find_first_of(forbidden) == std::string::npos &&
           std::any_of(name.begin(), name.end(), [](const char c) {
             return std::isalpha(static_cast<unsigned char>(c));
           });
  }

  void
  LabelNames::add(const Label        label,
                  const std::string &name,
                  const std::string &file,
                  const std::string &option)
  {
    if (!is_valid_name(name))
      throw InputError(file,
                       option,
                       "'" + name + "' cannot name label " +
                         std::to_string(label) +
                         "; expected one word with a letter and without "
                         "blanks or any of , : * \" #");
    const auto other = labels.find(name);
    if (other != labels.end() && other->second != label)
      throw InputError(file,
                       option,
                       "'" + name + "' names both label " +
                         std::to_string(other->second) + " and label " +
                         std::to_string(label) +
                         "; expected one label per name");
    const auto old = names.find(label);
    if (old != names.end() && old->second != name)
      throw InputError(file,
                       option,
                       "label " + std::to_string(label) + " is named both '" +
                         old->second + "' and '" + name +
                         "'; expected one name per label");
    names[label] = name;
    labels[name] = label;
  }

  std::optional<Label>
  LabelNames::find(const std::string &name) const
  {
    const auto it = labels.find(name);
    return it == labels.end() ? std::nullopt : std::optional<Label>(it->second);
  }

  std::string
  LabelNames::name(const Label label) const
  {
    const auto it = names.find(label);
    return it == names.end() ? std::string() : it->second;
  }

  bool
  LabelNames::empty() const
  {
    return names.empty();
  }

  const std::map<Label, std::string> &
  LabelNames::by_label() const
  {
    return names;
  }

  std::string
  LabelNames::known_text() const
  {
    constexpr unsigned int max_listed = 12;
    std::string            text;
    unsigned int           n = 0;
    for (const auto &[label, name] : names)
      {
        if (n++ == max_listed)
          return text + ", ... (" + std::to_string(names.size()) + " names)";
        text += (text.empty() ? "" : ", ") + name + " (" +
                std::to_string(label) + ")";
      }
    return text;
  }

  LabelNames
  read_label_names(const std::string &file, const std::string &option)
  {
    std::ifstream in =
      open_input(file, option, "a table of 'label name' lines");
    LabelNames   names;
    std::string  line;
    unsigned int line_number = 0;
    while (std::getline(in, line))
      {
        ++line_number;
        const std::string at = "line " + std::to_string(line_number) + ": ";
        line                 = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string        index, name;
        if (!(words >> index))
          continue;
        const auto range = label_range(index);
        if (!(words >> name) || !range || range->first != range->second)
          throw InputError(file,
                           option,
                           at +
                             "expected 'label name' with a label from 0 "
                             "to " +
                             std::to_string(max_label) + ", got '" +
                             dealii::Utilities::trim(line) + "'");
        try
          {
            names.add(range->first, name, file, option);
          }
        catch (const InputError &e)
          {
            throw InputError(file, option, at + e.message);
          }
      }
    if (names.empty())
      throw InputError(file,
                       option,
                       "the file names no label; expected 'label name' lines");
    return names;
  }

  void
  write_label_names(const LabelNames &names, std::ostream &out)
  {
    out << "# label name\n";
    for (const auto &[label, name] : names.by_label())
      out << label << ' ' << name << '\n';
  }

  std::string
  replace_label_names(const std::string &text,
                      const std::string &parameter,
                      const LabelNames  &names,
                      const bool         values)
  {
    std::vector<std::string> items;
    for (const std::string &item :
         dealii::Utilities::split_string_list(text, ','))
      if (!dealii::Utilities::trim(item).empty())
        items.push_back(dealii::Utilities::trim(item));
    std::set<std::string> known;
    for (const auto &[label, name] : names.by_label())
      known.insert(name);
    std::string result;
    for (const std::string &item : items)
      {
        const auto        colon = item.find(':');
        const std::string key = dealii::Utilities::trim(item.substr(0, colon));
        const std::string rest =
          colon == std::string::npos ? "" : item.substr(colon);
        std::string entry = item;
        const bool  lone_value =
          values && colon == std::string::npos && items.size() == 1;
        if (const auto label = names.find(key))
          entry = std::to_string(*label) + rest;
        else if (!(key == "*" || lone_value || label_range(key)) &&
                 !names.empty())
          throw InputError("",
                           parameter,
                           "'" + key +
                             "' is neither a label nor a tissue name of the "
                             "mesh" +
                             did_you_mean(nearest_names(key, known)) +
                             " (names: " + names.known_text() + ")");
        result += (result.empty() ? "" : ", ") + entry;
      }
    return result;
  }
} // namespace RestShape
