// VTK legacy meshes; read_mesh() by extension (Abaqus: abaqus_reader.cc).
#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/input_file.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/mesh_file_reading.h>
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
    const std::string legacy_format = "a VTK legacy ASCII unstructured grid";
  } // namespace

  namespace MeshFileReading
  {
    /// gmsh, VTK and Abaqus number hexahedron vertices counter-clockwise
    /// per face; deal.II lexicographically.
    constexpr unsigned int hex_order[8] = {0, 1, 3, 2, 4, 5, 7, 6};

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

    CellData<3>
    make_cell(const std::vector<unsigned int> &vertices)
    {
      CellData<3> cell(vertices.size());
      for (unsigned int v = 0; v < vertices.size(); ++v)
        cell.vertices[v] = vertices[vertices.size() == 8 ? hex_order[v] : v];
      return cell;
    }
  } // namespace MeshFileReading

  using namespace MeshFileReading;

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
      {
        const auto here = in.tellg();
        in.seekg(0, std::ios::end);
        end_of_file = in.tellg();
        in.seekg(here);
      }

      /// A count of items of @p words_per_item numbers each, checked
      /// against what the rest of the file can hold (two characters a
      /// number at least) before anything is allocated for them.
      long
      count(const std::string &what, const double words_per_item = 1)
      {
        const long n = integer(what);
        if (n < 0)
          fail(what + " declares " + std::to_string(n) + " items");
        const double left = double(end_of_file - in.tellg()) / 2 + 1;
        if (double(n) * words_per_item > left)
          fail(what + " declares " + std::to_string(n) +
               " items, more than the rest of the file holds");
        return n;
      }

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
        // Beyond 2^62 no count or index of a mesh is meant (and the
        // conversion to long would be undefined).
        constexpr double largest = 4.6e18;
        const double     x       = number(what);
        if (x != std::floor(x) || std::abs(x) > largest)
          fail("'" + number_text(x) + "' in " + what +
               " is not a whole number of at most " + number_text(largest));
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
      std::streampos    end_of_file;
    };

    /// CELLS of file version 5.1: OFFSETS and CONNECTIVITY arrays.
    std::vector<std::vector<long>>
    read_vtk_offsets(VtkWords &words, const long n_offsets, const long size)
    {
      words.word("OFFSETS type");
      if (n_offsets < 1)
        words.fail("OFFSETS needs at least one entry");
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
      // Each cell is at least two numbers ("1 v"); size counts them all.
      const long  n = words.count("CELLS", 2), size = words.count("CELLS");
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
          if (k < 0 || k > size)
            words.fail("a cell of " + std::to_string(k) +
                       " points in CELLS of size " + std::to_string(size));
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
              name                  = words.word("the array name");
              const long components = words.count(name);
              n_values              = words.count(name, double(components));
              n_values *= components;
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
            const long n = words.count("POINTS", 3);
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
            content.types.resize(words.count("CELL_TYPES"));
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
            // VTK's 0d-2d linear cells (vertex 1 ... quad 9) are ignored.
            if (type < 1 || type >= 10)
              fail(cell_text + " has VTK type " + std::to_string(type) +
                   ", not a linear tetrahedron (10) or hexahedron (12)");
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
    // Anything but a regular file is reported when the mesh is read.
    if (!is_regular_input(file))
      return {};
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
