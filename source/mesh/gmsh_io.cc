// Reading gmsh meshes with the gmsh library (every .msh version).
#include <gmsh.h>
#include <restshape/base/input_error.h>
#include <restshape/base/label_values.h>
#include <restshape/mesh/child_reader.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/gmsh_sections.h>
#include <restshape/mesh/mesh_parameters.h>
#include <restshape/mesh/mesh_transforms.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    const std::string &target_name      = gmsh_target_view;
    const std::string &mass_name        = gmsh_mass_ratio_view;
    const std::string &equilibrium_name = gmsh_equilibrium_view;
    /// gmsh's element types: linear and quadratic tetrahedra, hexahedra.
    constexpr int gmsh_tetrahedron = 4, gmsh_hexahedron = 5,
                  gmsh_tetrahedron_10 = 11;
    const auto &tet10_edges           = gmsh_tet10_edges;
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
          if (name != target_name && name != mass_name &&
              name != equilibrium_name)
            continue;
          std::string              type;
          std::vector<std::size_t> tags;
          std::vector<double>      data;
          double                   time       = 0;
          int                      components = 0;
          gmsh::view::getHomogeneousModelData(
            view, 0, type, tags, data, time, components);
          const bool  nodes = (name != mass_name);
          const auto &map   = nodes ? node_index : cell_of_element;
          if (components != (nodes ? 3 : 1) || tags.size() != map.size())
            throw InputError(file,
                             mesh_file_parameter,
                             "its " + name + " data do not cover every " +
                               (nodes ? "node" : "cell") +
                               " once; expected a rest_shape.msh as RestShape "
                               "writes it");
          if (name == target_name)
            mesh.targets.resize(mesh.vertices.size());
          else if (name == mass_name)
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
                  if (name == target_name)
                    mesh.targets[it->second] = p * length_unit;
                  else
                    {
                      mesh.rest_nodes.equilibria.push_back(
                        mesh.vertices[it->second]);
                      mesh.rest_nodes.equilibria.push_back(p * length_unit);
                    }
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

    /// The edge nodes of the 10-node tetrahedron @p element (its nodes
    /// @p nodes, its vertices @p cell) into @p mesh.rest_nodes.
    void
    add_edge_nodes(const std::size_t                          element,
                   const std::size_t                         *nodes,
                   const CellData<3>                         &cell,
                   const std::map<std::size_t, unsigned int> &index,
                   const std::string                         &file,
                   MeshDescription                           &mesh)
    {
      for (unsigned int k = 0; k < 6; ++k)
        {
          const auto it = index.find(nodes[4 + k]);
          if (it == index.end())
            throw InputError(file,
                             mesh_file_parameter,
                             "element " + std::to_string(element) +
                               " refers to a node that does not exist");
          for (const unsigned int v : tet10_edges[k])
            mesh.rest_nodes.edge_nodes.push_back(
              mesh.vertices[cell.vertices[v]]);
          mesh.rest_nodes.edge_nodes.push_back(mesh.vertices[it->second]);
        }
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
                  if (types[t] != gmsh_tetrahedron &&
                      types[t] != gmsh_hexahedron &&
                      types[t] != gmsh_tetrahedron_10)
                    throw InputError(
                      file,
                      mesh_file_parameter,
                      "the mesh has 3d elements of gmsh type " +
                        std::to_string(types[t]) +
                        "; expected only tetrahedra (4, or 11 with the "
                        "edge nodes of a quadratic rest shape) or "
                        "hexahedra (5)");
                  const bool quadratic = types[t] == gmsh_tetrahedron_10;
                  const unsigned int n =
                    types[t] == gmsh_hexahedron ? 8 : 4; // vertices
                  const unsigned int stride = quadratic ? 10 : n;
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
                            element_nodes[t][stride * e +
                                             (n == 4 ? v : hex_order[v])]);
                          if (it == index.end())
                            throw InputError(
                              file,
                              mesh_file_parameter,
                              "element " + std::to_string(element_tags[t][e]) +
                                " refers to a node that does not exist");
                          cell.vertices[v] = it->second;
                        }
                      cell.material_id = label;
                      if (quadratic)
                        add_edge_nodes(element_tags[t][e],
                                       &element_nodes[t][stride * e],
                                       cell,
                                       index,
                                       file,
                                       result);
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
} // namespace RestShape
