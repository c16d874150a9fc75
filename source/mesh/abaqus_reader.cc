// Abaqus input files (.inp): nodes, C3D4/C3D8 elements, element sets as
// labels.
#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/mesh_file_reading.h>
#include <restshape/mesh/mesh_formats.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>

namespace RestShape
{
  using namespace dealii;
  using namespace MeshFileReading;

  namespace
  {
    /// The comma-separated items of @p line, trimmed, in one pass (deal.II's
    /// split_string_list takes time quadratic in the number of items: more
    /// than a minute for a line of a million commas).
    std::vector<std::string>
    split_commas(const std::string &line)
    {
      std::vector<std::string> items;
      std::size_t              start = 0;
      for (;;)
        {
          const std::size_t comma = line.find(',', start);
          items.push_back(Utilities::trim(line.substr(
            start,
            comma == std::string::npos ? std::string::npos : comma - start)));
          if (comma == std::string::npos)
            break;
          start = comma + 1;
        }
      if (!items.empty() && items.back().empty())
        items.pop_back(); // a trailing comma
      return items;
    }

    /// An Abaqus keyword line "*Element, type=C3D4, elset=brain": the
    /// keyword and its options (lower-case keys).
    struct Keyword
    {
      std::string                        name;
      std::map<std::string, std::string> options;
    };

    Keyword
    parse_keyword(const std::string &line)
    {
      Keyword    k;
      const auto parts = split_commas(line.substr(1));
      k.name           = parts.empty() ? "" : lower(parts[0]);
      for (unsigned int i = 1; i < parts.size(); ++i)
        {
          const auto eq = parts[i].find('=');
          k.options[lower(Utilities::trim(parts[i].substr(0, eq)))] =
            eq == std::string::npos ? "" :
                                      Utilities::trim(parts[i].substr(eq + 1));
        }
      return k;
    }

    /// The whole numbers of a data line "1, 2, 3".
    std::vector<long>
    integers(const std::string &line,
             const std::string &file,
             const std::string &parameter,
             const unsigned int line_number)
    {
      std::vector<long> values;
      for (const std::string &item : split_commas(line))
        {
          if (item.empty())
            continue;
          char      *end = nullptr;
          const long v   = std::strtol(item.c_str(), &end, 10);
          if (end == item.c_str() || *end != '\0')
            throw InputError(file,
                             parameter,
                             "line " + std::to_string(line_number) + ": '" +
                               item + "' is not a whole number");
          values.push_back(v);
        }
      return values;
    }

    /// What an Abaqus file holds before it becomes a description.
    struct AbaqusModel
    {
      std::map<long, unsigned int>      node_index;
      std::vector<Point<3>>             nodes;
      std::map<long, std::vector<long>> elements; // 3d ones, by number
      std::map<long, unsigned int>      set_of;   // element -> set (ranges)
      std::vector<std::string>          sets;     // in order of appearance
      /// Element set assignments in file order (an element's ELSET=, an
      /// *Elset line, a GENERATE range): first, last, step and the set.
      struct Range
      {
        long         first, last, step;
        unsigned int set;
      };
      std::vector<Range> ranges;

      /// set_of from the assignments, in file order (a later set wins),
      /// for the elements that exist.
      void
      apply_ranges()
      {
        for (const Range &r : ranges)
          for (auto e = elements.lower_bound(r.first);
               e != elements.end() && e->first <= r.last;
               ++e)
            if ((e->first - r.first) % r.step == 0)
              set_of[e->first] = r.set;
      }

      unsigned int
      set_number(const std::string &name)
      {
        const auto it = std::find(sets.begin(), sets.end(), name);
        if (it != sets.end())
          return it - sets.begin();
        sets.push_back(name);
        return sets.size() - 1;
      }
    };

    AbaqusModel
    read_abaqus_model(const std::string &file, const std::string &parameter)
    {
      std::ifstream in = open(file, parameter);
      AbaqusModel   model;
      std::string   line, block;
      Keyword       keyword;
      unsigned int  line_number = 0, nodes_per_element = 0;
      long          set  = -1;
      const auto    fail = [&](const std::string &message) {
        throw InputError(file,
                         parameter,
                         "line " + std::to_string(line_number) + ": " +
                           message);
      };
      while (std::getline(in, line))
        {
          ++line_number;
          line = Utilities::trim(line);
          if (line.empty() || line.rfind("**", 0) == 0)
            continue;
          if (line[0] == '*')
            {
              keyword = parse_keyword(line);
              block   = keyword.name;
              set     = -1;
              if (block == "element")
                {
                  const std::string type = lower(keyword.options["type"]);
                  nodes_per_element      = type == "c3d4" ? 4 :
                                           type == "c3d8" ? 8 :
                                                            0;
                  if (nodes_per_element == 0 && type.rfind("c3d", 0) == 0)
                    fail("element type " + keyword.options["type"] +
                         "; expected C3D4 or C3D8 (linear tetrahedra or "
                         "hexahedra)");
                }
              const std::string elset = keyword.options["elset"];
              if ((block == "element" && nodes_per_element > 0 &&
                   !elset.empty()) ||
                  block == "elset")
                {
                  if (elset.empty())
                    fail("*Elset without ELSET=");
                  set = model.set_number(elset);
                }
              continue;
            }
          if (block == "node")
            {
              const auto items = split_commas(line);
              if (items.size() < 4)
                fail("expected 'number, x, y, z'");
              const std::vector<long> number =
                integers(items[0], file, parameter, line_number);
              if (number.size() != 1)
                fail("'" + items[0] +
                     "' is not a node number; expected 'number, x, y, z'");
              Point<3> x;
              for (unsigned int d = 0; d < 3; ++d)
                {
                  const std::string item = Utilities::trim(items[d + 1]);
                  char             *end  = nullptr;
                  x[d]                   = std::strtod(item.c_str(), &end);
                  if (end == item.c_str() || *end != '\0' ||
                      !std::isfinite(x[d]))
                    fail("'" + item + "' is not a finite coordinate");
                }
              model.node_index[number[0]] = model.nodes.size();
              model.nodes.push_back(x);
            }
          else if (block == "element" && nodes_per_element > 0)
            {
              const std::vector<long> v =
                integers(line, file, parameter, line_number);
              if (v.size() != nodes_per_element + 1)
                fail("expected the element's number and " +
                     std::to_string(nodes_per_element) + " nodes");
              model.elements[v[0]].assign(v.begin() + 1, v.end());
              if (set >= 0)
                model.ranges.push_back(
                  {v[0], v[0], 1, static_cast<unsigned int>(set)});
            }
          else if (block == "elset")
            {
              std::vector<long> v =
                integers(line, file, parameter, line_number);
              if (keyword.options.count("generate"))
                {
                  if (v.size() < 2 || v.size() > 3 ||
                      (v.size() == 3 && v[2] <= 0))
                    fail("expected 'first, last[, step]' for GENERATE");
                  // Kept as a range: it may span far more numbers than
                  // there are elements (1e9 of them took all the memory).
                  model.ranges.push_back({v[0],
                                          v[1],
                                          v.size() == 3 ? v[2] : 1,
                                          static_cast<unsigned int>(set)});
                  continue;
                }
              for (const long e : v)
                model.ranges.push_back(
                  {e, e, 1, static_cast<unsigned int>(set)});
            }
        }
      model.apply_ranges();
      return model;
    }
  } // namespace

  MeshDescription
  read_abaqus_mesh(const std::string &file,
                   const double       length_unit,
                   const std::string &parameter)
  {
    AbaqusModel     model = read_abaqus_model(file, parameter);
    MeshDescription mesh;
    for (const Point<3> &x : model.nodes)
      mesh.vertices.push_back(x * length_unit);
    // Sets that hold 3d elements become labels 1, 2, ...
    std::map<unsigned int, Label> label_of_set;
    for (const auto &[element, nodes] : model.elements)
      {
        const auto set = model.set_of.find(element);
        if (set == model.set_of.end())
          throw InputError(file,
                           parameter,
                           "element " + std::to_string(element) +
                             " is in no element set; expected every "
                             "element labelled by an ELSET");
        label_of_set.emplace(set->second, 0);
        std::vector<unsigned int> v;
        for (const long n : nodes)
          {
            const auto it = model.node_index.find(n);
            if (it == model.node_index.end())
              throw InputError(file,
                               parameter,
                               "element " + std::to_string(element) +
                                 " refers to node " + std::to_string(n) +
                                 ", which does not exist");
            v.push_back(it->second);
          }
        mesh.cells.push_back(make_cell(v));
        mesh.cells.back().material_id = set->second;
      }
    Label next = 1;
    for (auto &[set, label] : label_of_set)
      {
        label = next++;
        if (LabelNames::is_valid_name(model.sets[set]))
          mesh.names.add(label, model.sets[set], file, parameter);
      }
    for (auto &cell : mesh.cells)
      cell.material_id = label_of_set[cell.material_id];
    return finish_read_mesh(std::move(mesh), file, parameter);
  }

} // namespace RestShape
