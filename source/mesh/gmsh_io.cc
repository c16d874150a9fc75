// Reading and writing gmsh meshes (the gmsh library reads, we write 2.2 ASCII).
#include <gmsh.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/base/label_values.h>
#include <restshape/mesh/child_reader.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/gmsh_sections.h>
#include <restshape/mesh/mesh_parameters.h>
#include <restshape/mesh/mesh_transforms.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    const std::string target_name = "target_position";
    const std::string mass_name   = "image_mass_ratio";
    /// Bounds of an image-to-rest mass ratio (the volume ratio of a cell
    /// between the image and the rest shape): beyond them the file is not
    /// a rest shape of soft tissue.
    constexpr double smallest_mass_ratio = 1e-3;
    constexpr double largest_mass_ratio  = 1e3;

    /// The node data "target_position" and element data "image_mass_ratio"
    /// of the file open in gmsh (none, or both for every node and cell).
    void
    read_rest_shape_data(
      const std::string                         &file,
      const std::map<std::size_t, unsigned int> &node_index,
      const std::map<std::size_t, unsigned int> &cell_of_element,
      const double                               length_unit,
      MeshDescription                           &mesh)
    {
      std::vector<int> views;
      gmsh::view::getTags(views);
      for (const int view : views)
        {
          std::string name;
          gmsh::option::getString("View[" +
                                    std::to_string(gmsh::view::getIndex(view)) +
                                    "].Name",
                                  name);
          if (name != target_name && name != mass_name)
            continue;
          std::string              type;
          std::vector<std::size_t> tags;
          std::vector<double>      data;
          double                   time       = 0;
          int                      components = 0;
          gmsh::view::getHomogeneousModelData(
            view, 0, type, tags, data, time, components);
          const bool  nodes = (name == target_name);
          const auto &map   = nodes ? node_index : cell_of_element;
          if (components != (nodes ? 3 : 1) || tags.size() != map.size())
            throw InputError(file,
                             mesh_file_parameter,
                             "its " + name + " data do not cover every " +
                               (nodes ? "node" : "cell") +
                               " once; expected a rest_shape.msh as RestShape "
                               "writes it");
          if (nodes)
            mesh.targets.resize(mesh.vertices.size());
          else
            mesh.mass_ratios.resize(mesh.cells.size());
          for (unsigned int k = 0; k < tags.size(); ++k)
            {
              const auto it = map.find(tags[k]);
              if (it == map.end())
                throw InputError(file,
                                 mesh_file_parameter,
                                 name + " refers to " +
                                   std::to_string(tags[k]) +
                                   ", which is not in the mesh");
              if (nodes)
                {
                  const Point<3> p(data[3 * k],
                                   data[3 * k + 1],
                                   data[3 * k + 2]);
                  if (!std::isfinite(p.norm_square()))
                    throw InputError(file,
                                     mesh_file_parameter,
                                     name + " of node " +
                                       std::to_string(tags[k]) +
                                       " is not a finite point; expected "
                                       "three finite coordinates");
                  mesh.targets[it->second] = p * length_unit;
                }
              else if (!(data[k] >= smallest_mass_ratio &&
                         data[k] <= largest_mass_ratio))
                throw InputError(file,
                                 mesh_file_parameter,
                                 name + " of element " +
                                   std::to_string(tags[k]) + " is " +
                                   number_text(data[k]) + "; expected " +
                                   number_text(smallest_mass_ratio) +
                                   " <= ratio <= " +
                                   number_text(largest_mass_ratio));
              else
                mesh.mass_ratios[it->second] = data[k];
            }
        }
      if (mesh.targets.empty() != mesh.mass_ratios.empty())
        throw InputError(file,
                         mesh_file_parameter,
                         "it has " +
                           (mesh.targets.empty() ? mass_name : target_name) +
                           " data without " +
                           (mesh.targets.empty() ? target_name : mass_name) +
                           "; expected both (a rest_shape.msh) or neither");
    }

    /// gmsh 2.2 $NodeData/$ElementData of a rest shape.
    void
    write_rest_shape_data(std::ostream            &out,
                          const std::vector<bool> &used,
                          const RestShapeData     &rest,
                          const double             length_unit)
    {
      out << "$NodeData\n1\n\"" << target_name << "\"\n1\n0\n3\n0\n3\n"
          << std::count(used.begin(), used.end(), true) << '\n';
      for (unsigned int v = 0; v < used.size(); ++v)
        if (used[v])
          {
            const Point<3> p = rest.target(v) / length_unit;
            out << v + 1 << ' ' << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
          }
      out << "$EndNodeData\n$ElementData\n1\n\"" << mass_name
          << "\"\n1\n0\n3\n0\n1\n"
          << rest.mass_ratios.size() << '\n';
      for (unsigned int c = 0; c < rest.mass_ratios.size(); ++c)
        out << c + 1 << ' ' << rest.mass_ratios[c] << '\n';
      out << "$EndElementData\n";
    }

    /// One cell to write: its label and vertices in deal.II's order.
    using CellWriter =
      std::function<void(Label, const std::vector<unsigned int> &)>;
    /// Calls its argument once per cell, in the order of the file.
    using CellVisitor = std::function<void(const CellWriter &)>;

    /// gmsh 2.2 $PhysicalNames of the labels of the cells that have names.
    void
    write_physical_names(std::ostream                     &out,
                         const CellVisitor                &cells,
                         const LabelNames                 &names,
                         const std::map<int, std::string> &surface_names)
    {
      std::set<Label> labels;
      cells([&](const Label label, const std::vector<unsigned int> &) {
        if (!names.name(label).empty())
          labels.insert(label);
      });
      if (labels.empty() && surface_names.empty())
        return;
      out << "$PhysicalNames\n" << labels.size() + surface_names.size() << '\n';
      for (const auto &[tag, name] : surface_names)
        out << "2 " << tag << " \"" << name << "\"\n";
      for (const Label l : labels)
        out << "3 " << l << " \"" << names.name(l) << "\"\n";
      out << "$EndPhysicalNames\n";
    }

    /// write_gmsh() for the cells that @p cells visits (@p n_vertices
    /// vertex indices, @p n_cells cells).
    void
    write_cells(const CellVisitor                           &cells,
                const unsigned int                           n_vertices,
                const unsigned int                           n_cells,
                const std::function<Point<3>(unsigned int)> &position,
                const double                                 length_unit,
                const std::string                           &file,
                const RestShapeData                         *rest,
                const LabelNames                            &names,
                const std::vector<SurfaceTriangle>          &surfaces      = {},
                const std::map<int, std::string>            &surface_names = {})
    {
      std::vector<bool> used(n_vertices, false);
      cells([&](Label, const std::vector<unsigned int> &vertices) {
        for (const unsigned int v : vertices)
          used[v] = true;
      });
      write_file_atomically(
        file,
        [&](std::ostream &out) {
          out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
          write_physical_names(out, cells, names, surface_names);
          out << "$Nodes\n"
              << std::count(used.begin(), used.end(), true) << '\n'
              << std::setprecision(16);
          for (unsigned int v = 0; v < used.size(); ++v)
            if (used[v])
              {
                const Point<3> p = position(v) / length_unit;
                out << v + 1 << ' ' << p[0] << ' ' << p[1] << ' ' << p[2]
                    << '\n';
              }
          out << "$EndNodes\n$Elements\n" << n_cells + surfaces.size() << '\n';
          // gmsh numbers hexahedron vertices counter-clockwise per face.
          static const unsigned int hex_order[8] = {0, 1, 3, 2, 4, 5, 7, 6};
          unsigned int              n            = 0;
          cells([&](const Label label, const std::vector<unsigned int> &v) {
            const bool tet = v.size() == 4;
            out << ++n << (tet ? " 4 2 " : " 5 2 ") << label << ' ' << label;
            for (unsigned int k = 0; k < v.size(); ++k)
              out << ' ' << v[tet ? k : hex_order[k]] + 1;
            out << '\n';
          });
          for (const SurfaceTriangle &t : surfaces)
            out << ++n << " 2 2 " << t.tag << ' ' << t.tag << ' '
                << t.vertices[0] + 1 << ' ' << t.vertices[1] + 1 << ' '
                << t.vertices[2] + 1 << '\n';
          out << "$EndElements\n";
          if (rest != nullptr)
            write_rest_shape_data(out, used, *rest, length_unit);
        },
        "Output/Directory");
    }
  } // namespace

  LabelNames
  read_gmsh_label_names(const std::string &file)
  {
    LabelNames    names;
    std::ifstream in(file, std::ios::binary);
    std::string   line;
    // $PhysicalNames comes before the nodes and elements.
    while (std::getline(in, line) && line.rfind("$Nodes", 0) != 0 &&
           line.rfind("$Entities", 0) != 0)
      if (line.rfind("$PhysicalNames", 0) == 0)
        {
          unsigned int n = 0;
          in >> n;
          std::getline(in, line);
          for (unsigned int i = 0; i < n && std::getline(in, line); ++i)
            {
              std::istringstream words(line);
              int                dim = 0;
              long               tag = -1;
              words >> dim >> tag;
              const auto first = line.find('"'), last = line.rfind('"');
              if (!words || dim != 3 || tag < 0 || tag > max_label ||
                  first == std::string::npos || last <= first)
                continue;
              const std::string name = line.substr(first + 1, last - first - 1);
              if (LabelNames::is_valid_name(name) && !names.find(name))
                names.add(Label(tag), name, file, mesh_file_parameter);
            }
          break;
        }
    return names;
  }

  namespace
  {
    MeshDescription
    read_gmsh_data(const std::string &file, const double length_unit);
  } // namespace

  MeshDescription
  read_gmsh(const std::string &file, const double length_unit)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(file, ec))
      throw InputError(file,
                       mesh_file_parameter,
                       "no such file; expected a gmsh .msh mesh");
    if (!fs::is_regular_file(file, ec) || ::access(file.c_str(), R_OK) != 0)
      throw InputError(file,
                       mesh_file_parameter,
                       "not a readable file; expected a gmsh .msh mesh");
    check_gmsh_section_counts(file, mesh_file_parameter);
    // gmsh's reader crashes or corrupts its heap on some malformed files
    // (gmsh 2 elements with bad partition tags, found by fuzzing): it runs
    // in a child process, and a crash is an input error.
    MeshDescription mesh =
      read_in_child_process([&]() { return read_gmsh_data(file, length_unit); },
                            file,
                            mesh_file_parameter,
                            "a well-formed gmsh .msh mesh");
    mesh.names = read_gmsh_label_names(file);
    return finish_read_mesh(std::move(mesh), file, mesh_file_parameter);
  }

  namespace
  {
    /// Nodes, cells and rest-shape data as gmsh reads them.
    MeshDescription
    read_gmsh_data(const std::string &file, const double length_unit)
    {
      // The gmsh library reads every .msh version (ASCII or binary) and, unlike
      // GridIn (which silently reorders the vertices of inverted tetrahedra),
      // returns the connectivity in file order, which the orientation check
      // needs.
      MeshDescription result;
      gmsh::initialize(0, nullptr, false);
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::option::setNumber("General.Verbosity", 0);
      try
        {
          gmsh::open(file);

          std::vector<std::size_t> node_tags;
          std::vector<double>      coordinates, parametric;
          gmsh::model::mesh::getNodes(node_tags, coordinates, parametric);
          std::map<std::size_t, unsigned int> index;
          for (unsigned int n = 0; n < node_tags.size(); ++n)
            {
              for (unsigned int d = 0; d < 3; ++d)
                if (!std::isfinite(coordinates[3 * n + d]))
                  throw InputError(
                    file,
                    mesh_file_parameter,
                    "node " + std::to_string(node_tags[n]) +
                      " has a coordinate that is not a finite number");
              index[node_tags[n]] = n;
              result.vertices.emplace_back(coordinates[3 * n] * length_unit,
                                           coordinates[3 * n + 1] * length_unit,
                                           coordinates[3 * n + 2] *
                                             length_unit);
            }

          std::map<std::size_t, unsigned int> cell_of_element;
          gmsh::vectorpair                    entities;
          gmsh::model::getEntities(entities, 3);
          for (const auto &[dim, entity] : entities)
            {
              // The label: the entity's physical group, or its own tag.
              std::vector<int> physical;
              gmsh::model::getPhysicalGroupsForEntity(dim, entity, physical);
              const int label = physical.empty() ? entity : physical[0];
              if (label < 0)
                throw InputError(file,
                                 mesh_file_parameter,
                                 "volume tag " + std::to_string(label) +
                                   " is not a valid label; expected 0.." +
                                   std::to_string(max_label));

              std::vector<int>                      types;
              std::vector<std::vector<std::size_t>> element_tags, element_nodes;
              gmsh::model::mesh::getElements(
                types, element_tags, element_nodes, dim, entity);
              for (unsigned int t = 0; t < types.size(); ++t)
                {
                  if (types[t] != 4 && types[t] != 5)
                    throw InputError(
                      file,
                      mesh_file_parameter,
                      "the mesh has 3d elements of gmsh type " +
                        std::to_string(types[t]) +
                        "; expected only linear tetrahedra (4) or "
                        "hexahedra (5)");
                  const unsigned int n = (types[t] == 4 ? 4 : 8);
                  // gmsh numbers hexahedron vertices counter-clockwise per
                  // face.
                  static const unsigned int hex_order[8] = {
                    0, 1, 3, 2, 4, 5, 7, 6};
                  for (unsigned int e = 0; e < element_tags[t].size(); ++e)
                    {
                      CellData<3> cell(n);
                      for (unsigned int v = 0; v < n; ++v)
                        {
                          const auto it = index.find(
                            element_nodes[t]
                                         [n * e + (n == 4 ? v : hex_order[v])]);
                          if (it == index.end())
                            throw InputError(
                              file,
                              mesh_file_parameter,
                              "element " + std::to_string(element_tags[t][e]) +
                                " refers to a node that does not exist");
                          cell.vertices[v] = it->second;
                        }
                      cell.material_id = label;
                      result.cells.push_back(cell);
                      cell_of_element[element_tags[t][e]] =
                        result.cells.size() - 1;
                    }
                }
            }
          read_rest_shape_data(
            file, index, cell_of_element, length_unit, result);
        }
      catch (const InputError &)
        {
          gmsh::finalize();
          throw;
        }
      catch (...)
        {
          std::string message;
          gmsh::logger::getLastError(message);
          gmsh::finalize();
          throw InputError(file,
                           mesh_file_parameter,
                           "not a valid gmsh mesh (" +
                             (message.empty() ? std::string("unreadable") :
                                                message) +
                             "); expected a gmsh .msh file with 3d cells");
        }
      gmsh::finalize();
      return result;
    }
  } // namespace

  MeshDescription
  finish_read_mesh(MeshDescription    mesh,
                   const std::string &file,
                   const std::string &parameter)
  {
    if (mesh.cells.empty())
      throw InputError(file, parameter, "the mesh has no 3d cells");
    for (const auto &cell : mesh.cells)
      if (cell.vertices.size() != mesh.cells[0].vertices.size())
        throw InputError(file,
                         parameter,
                         "the mesh mixes tetrahedra and hexahedra; expected "
                         "only one cell type");
    // Drop vertices that no cell uses (e.g. of boundary-only entities).
    std::vector<unsigned int> all(mesh.cells.size());
    std::iota(all.begin(), all.end(), 0u);
    const LabelNames names = mesh.names;
    mesh                   = select_cells(mesh, all);
    mesh.names             = names;
    return mesh;
  }

  void
  write_gmsh(const MeshDescription              &mesh,
             const double                        length_unit,
             const std::string                  &file,
             const std::vector<SurfaceTriangle> &surfaces,
             const std::map<int, std::string>   &surface_names)
  {
    const CellVisitor cells = [&](const CellWriter &write) {
      for (const auto &cell : mesh.cells)
        write(cell.material_id, cell.vertices);
    };
    write_cells(
      cells,
      mesh.vertices.size(),
      mesh.cells.size(),
      [&](const unsigned int v) { return mesh.vertices[v]; },
      length_unit,
      file,
      nullptr,
      mesh.names,
      surfaces,
      surface_names);
  }

  void
  write_gmsh(const Triangulation<3>                      &tria,
             const std::function<Point<3>(unsigned int)> &position,
             const double                                 length_unit,
             const std::string                           &file,
             const RestShapeData                         *rest,
             const LabelNames                            &names)
  {
    std::vector<unsigned int> vertices;
    const CellVisitor         cells = [&](const CellWriter &write) {
      for (const auto &cell : tria.active_cell_iterators())
        {
          vertices.resize(cell->n_vertices());
          for (unsigned int v = 0; v < cell->n_vertices(); ++v)
            vertices[v] = cell->vertex_index(v);
          write(cell->material_id(), vertices);
        }
    };
    write_cells(cells,
                tria.n_vertices(),
                tria.n_active_cells(),
                position,
                length_unit,
                file,
                rest,
                names);
  }

  void
  write_gmsh(const MeshDescription                       &mesh,
             const std::function<Point<3>(unsigned int)> &position,
             const double                                 length_unit,
             const std::string                           &file,
             const RestShapeData                         *rest,
             const LabelNames                            &names)
  {
    const CellVisitor cells = [&](const CellWriter &write) {
      for (const auto &cell : mesh.cells)
        write(cell.material_id, cell.vertices);
    };
    write_cells(cells,
                mesh.vertices.size(),
                mesh.cells.size(),
                position,
                length_unit,
                file,
                rest,
                names);
  }
} // namespace RestShape
