// VTK legacy and Abaqus meshes; read_mesh() by extension.
#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/mesh_formats.h>
#include <restshape/mesh/mesh_transforms.h>
#include <restshape/mesh/vtk_grid.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// gmsh, VTK and Abaqus number hexahedron vertices counter-clockwise
    /// per face; deal.II lexicographically.
    constexpr unsigned int hex_order[8] = {0, 1, 3, 2, 4, 5, 7, 6};

    const std::string legacy_format = "a VTK legacy ASCII unstructured grid";

    std::string
    lower(std::string text)
    {
      for (char &c : text)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return text;
    }

    std::ifstream
    open(const std::string &file, const std::string &parameter)
    {
      std::error_code ec;
      if (!std::filesystem::is_regular_file(file, ec))
        throw InputError(file, parameter, "no such file");
      std::ifstream in(file);
      if (!in)
        throw InputError(file, parameter, "not a readable file");
      return in;
    }

    /// A cell from its vertex numbers in file order (hexahedra reordered).
    CellData<3>
    make_cell(const std::vector<unsigned int> &vertices)
    {
      CellData<3> cell(vertices.size());
      for (unsigned int v = 0; v < vertices.size(); ++v)
        cell.vertices[v] = vertices[vertices.size() == 8 ? hex_order[v] : v];
      return cell;
    }

  } // namespace

  // ---------------------------------------------------------------- VTK

  namespace
  {
    /// Whitespace-separated words of a VTK file, with the line of each.
    class VtkWords
    {
    public:
      VtkWords(std::istream &in, std::string file, std::string parameter)
        : in(in)
        , file(std::move(file))
        , parameter(std::move(parameter))
      {}

      bool
      next(std::string &word)
      {
        return static_cast<bool>(in >> word);
      }

      std::string
      word(const std::string &what)
      {
        std::string w;
        if (!(in >> w))
          fail("the file ends before " + what);
        return w;
      }

      double
      number(const std::string &what)
      {
        const std::string w   = word(what);
        char             *end = nullptr;
        const double      x   = std::strtod(w.c_str(), &end);
        if (end == w.c_str() || *end != '\0' || !std::isfinite(x))
          fail("'" + w + "' in " + what + " is not a finite number");
        return x;
      }

      long
      integer(const std::string &what)
      {
        const double x = number(what);
        if (x != std::floor(x))
          fail("'" + std::to_string(x) + "' in " + what +
               " is not a whole number");
        return static_cast<long>(x);
      }

      [[noreturn]] void
      fail(const std::string &message) const
      {
        throw InputError(file,
                         parameter,
                         message + "; expected " + legacy_format);
      }

      void
      skip_line()
      {
        std::string rest;
        std::getline(in, rest);
      }

    private:
      std::istream     &in;
      const std::string file, parameter;
    };

    /// CELLS of file version 5.1: OFFSETS and CONNECTIVITY arrays.
    std::vector<std::vector<long>>
    read_vtk_offsets(VtkWords &words, const long n_offsets, const long size)
    {
      words.word("OFFSETS type");
      std::vector<long> offsets(n_offsets);
      for (long &o : offsets)
        o = words.integer("OFFSETS");
      if (words.word("CONNECTIVITY") != "CONNECTIVITY")
        words.fail("no CONNECTIVITY after OFFSETS");
      words.word("CONNECTIVITY type");
      std::vector<long> connectivity(size);
      for (long &v : connectivity)
        v = words.integer("CONNECTIVITY");
      std::vector<std::vector<long>> cells;
      for (long c = 0; c + 1 < n_offsets; ++c)
        {
          if (offsets[c] < 0 || offsets[c + 1] < offsets[c] ||
              offsets[c + 1] > size)
            words.fail("OFFSETS out of range");
          cells.emplace_back(connectivity.begin() + offsets[c],
                             connectivity.begin() + offsets[c + 1]);
        }
      return cells;
    }

    /// The label array's name among the cell arrays, by preference.
  } // namespace

  namespace
  {
    using VtkContent = VtkGrid;

    /// CELLS: "n size", then "k v0 ... v(k-1)" per cell, or (file version
    /// 5.1) OFFSETS and CONNECTIVITY arrays.
    std::vector<std::vector<long>>
    read_vtk_cells(VtkWords &words)
    {
      const long  n = words.integer("CELLS"), size = words.integer("CELLS");
      std::string peek = words.word("CELLS");
      if (peek == "OFFSETS")
        return read_vtk_offsets(words, n, size);
      std::vector<std::vector<long>> cells(n);
      char                          *end = nullptr;
      long                           k   = std::strtol(peek.c_str(), &end, 10);
      if (end == peek.c_str() || *end != '\0')
        words.fail("'" + peek + "' in CELLS is not a whole number");
      for (long c = 0; c < n; ++c)
        {
          if (c > 0)
            k = words.integer("CELLS");
          cells[c].resize(k);
          for (long &v : cells[c])
            v = words.integer("CELLS");
        }
      return cells;
    }

    /// SCALARS name type [n]; LOOKUP_TABLE t; values. FIELD name k; then k
    /// arrays "name components tuples type" and values. Arrays with one
    /// value per cell go into @p content.
    void
    read_vtk_arrays(VtkWords &words, const bool scalars, VtkContent &content)
    {
      std::string name     = words.word("the array name");
      long        n_arrays = 1;
      if (scalars)
        words.skip_line();
      else
        n_arrays = words.integer("FIELD");
      for (long a = 0; a < n_arrays; ++a)
        {
          long n_values = content.types.size();
          if (scalars)
            {
              if (words.word("LOOKUP_TABLE") != "LOOKUP_TABLE")
                words.fail("no LOOKUP_TABLE after SCALARS " + name);
              words.word("the lookup table");
            }
          else
            {
              name     = words.word("the array name");
              n_values = words.integer(name) * words.integer(name);
              words.word("the array type");
            }
          std::vector<double> values(n_values);
          for (double &v : values)
            v = words.number(name);
          if (n_values == long(content.types.size()))
            content.arrays[name].assign(values.begin(), values.end());
        }
    }

    /// Everything after the DATASET line, up to POINT_DATA.
    VtkContent
    read_vtk_content(VtkWords &words, const double length_unit)
    {
      VtkContent  content;
      std::string key;
      while (words.next(key))
        if (key == "POINTS")
          {
            const long n = words.integer("POINTS");
            words.word("the POINTS type");
            for (long p = 0; p < n; ++p)
              {
                Point<3> x;
                for (unsigned int d = 0; d < 3; ++d)
                  x[d] = words.number("POINTS") * length_unit;
                content.points.push_back(x);
              }
          }
        else if (key == "CELLS")
          content.cells = read_vtk_cells(words);
        else if (key == "CELL_TYPES")
          {
            content.types.resize(words.integer("CELL_TYPES"));
            for (long &t : content.types)
              t = words.integer("CELL_TYPES");
          }
        else if (key == "SCALARS" || key == "FIELD")
          read_vtk_arrays(words, key == "SCALARS", content);
        else if (key == "CELL_DATA")
          words.integer("CELL_DATA");
        else if (key == "POINT_DATA")
          break; // only cell data is read
        else
          words.fail("unexpected '" + key + "'");
      if (content.cells.size() != content.types.size())
        words.fail("CELLS and CELL_TYPES differ in length");
      return content;
    }
  } // namespace

  std::string
  vtk_label_array(const std::map<std::string, std::vector<long>> &arrays,
                  const std::function<void(const std::string &)> &fail)
  {
    for (const std::string name : {"label",
                                   "labels",
                                   "MaterialID",
                                   "material_id",
                                   "gmsh:physical",
                                   "CellEntityIds",
                                   "region"})
      if (arrays.count(name))
        return name;
    if (arrays.size() == 1)
      return arrays.begin()->first;
    std::string names;
    for (const auto &[name, values] : arrays)
      names += (names.empty() ? "" : ", ") + name;
    fail("no cell-data label array (found: " +
         (names.empty() ? std::string("none") : names) +
         "); expected an integer array named label or MaterialID");
    return "";
  }

  MeshDescription
  read_vtk_mesh(const std::string &file,
                const double       length_unit,
                const std::string &parameter)
  {
    std::ifstream in = open(file, parameter);
    std::string   header, title;
    std::getline(in, header);
    std::getline(in, title);
    VtkWords words(in, file, parameter);
    if (header.rfind("# vtk DataFile", 0) != 0)
      words.fail("no '# vtk DataFile' header");
    if (words.word("the format") != "ASCII")
      words.fail("binary VTK is not read");
    if (words.word("DATASET") != "DATASET" ||
        words.word("the dataset type") != "UNSTRUCTURED_GRID")
      words.fail("not an unstructured grid");

    return vtk_grid_to_mesh(read_vtk_content(words, length_unit),
                            file,
                            parameter,
                            legacy_format);
  }

  MeshDescription
  vtk_grid_to_mesh(const VtkGrid     &grid,
                   const std::string &file,
                   const std::string &parameter,
                   const std::string &format)
  {
    const auto fail = [&](const std::string &message) {
      throw InputError(file, parameter, message + "; expected " + format);
    };
    const std::vector<long> &labels =
      grid.arrays.at(vtk_label_array(grid.arrays, fail));
    MeshDescription mesh;
    mesh.vertices = grid.points;
    for (unsigned int i = 0; i < grid.cells.size(); ++i)
      {
        const std::string cell_text = "cell " + std::to_string(i);
        const long        type      = grid.types[i];
        if (type != 10 && type != 12)
          {
            if (type >= 10)
              fail(cell_text + " has VTK type " + std::to_string(type) +
                   "; expected linear tetrahedra (10) or hexahedra (12)");
            continue; // vertices, lines, faces
          }
        std::vector<unsigned int> v;
        for (const long p : grid.cells[i])
          {
            if (p < 0 || p >= long(mesh.vertices.size()))
              fail(cell_text + " refers to a point that does not exist");
            v.push_back(p);
          }
        if (v.size() != (type == 10 ? 4u : 8u))
          fail(cell_text + " has " + std::to_string(v.size()) +
               " points for its type");
        if (labels[i] < 0 || labels[i] > max_label)
          fail(cell_text + " has label " + std::to_string(labels[i]) +
               ", outside 0.." + std::to_string(max_label));
        CellData<3> cell = make_cell(v);
        cell.material_id = Label(labels[i]);
        mesh.cells.push_back(cell);
      }
    return finish_read_mesh(std::move(mesh), file, parameter);
  }

  // ------------------------------------------------------------- Abaqus

  namespace
  {
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
      const auto parts = Utilities::split_string_list(line.substr(1), ',');
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
      for (const std::string &item : Utilities::split_string_list(line, ','))
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
      std::map<long, unsigned int>      set_of;   // element -> set
      std::vector<std::string>          sets;     // in order of appearance

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
              const auto items = Utilities::split_string_list(line, ',');
              if (items.size() < 4)
                fail("expected 'number, x, y, z'");
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
              model.node_index[integers(
                items[0], file, parameter, line_number)[0]] =
                model.nodes.size();
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
                model.set_of[v[0]] = set;
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
                  const long        step = v.size() == 3 ? v[2] : 1;
                  std::vector<long> range;
                  for (long e = v[0]; e <= v[1]; e += step)
                    range.push_back(e);
                  v = range;
                }
              for (const long e : v)
                model.set_of[e] = set;
            }
        }
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

  // ---------------------------------------------------- by extension

  namespace
  {
    std::string
    extension(const std::string &file)
    {
      return lower(std::filesystem::path(file).extension().string());
    }
  } // namespace

  MeshDescription
  read_mesh(const std::string &file,
            const double       length_unit,
            const std::string &parameter)
  {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
      throw InputError(
        file,
        parameter,
        "no such file; expected a mesh (.msh, .vtk, .vtu or .inp)");
    if (!std::filesystem::is_regular_file(file, ec) ||
        !std::ifstream(file).good())
      throw InputError(file,
                       parameter,
                       "not a readable file; expected a mesh (.msh, .vtk, "
                       ".vtu or .inp)");
    const std::string ext = extension(file);
    if (ext == ".msh")
      return read_gmsh(file, length_unit);
    if (ext == ".vtk")
      return read_vtk_mesh(file, length_unit, parameter);
    if (ext == ".vtu")
      return read_vtu_mesh(file, length_unit, parameter);
    if (ext == ".inp")
      return read_abaqus_mesh(file, length_unit, parameter);
    throw InputError(file,
                     parameter,
                     "unknown mesh format '" + ext +
                       "'; expected .msh (gmsh), .vtk (VTK legacy ASCII "
                       "unstructured grid), .vtu (VTK XML unstructured grid) "
                       "or .inp (Abaqus)");
  }

  LabelNames
  read_mesh_label_names(const std::string &file)
  {
    const std::string ext = extension(file);
    if (ext == ".msh")
      return read_gmsh_label_names(file);
    if (ext == ".inp")
      try
        {
          return read_abaqus_mesh(file, 1, "Mesh/File").names;
        }
      catch (const InputError &)
        {
          // Reported when the mesh itself is read.
        }
    return LabelNames();
  }
} // namespace RestShape
