// Reading and writing gmsh meshes (the gmsh library reads, we write 2.2 ASCII).
#include <gmsh.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/mesh_transforms.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <numeric>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    const std::string file_parameter = "Mesh/File";
  }

  MeshDescription
  read_gmsh(const std::string &file, const double length_unit)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(file, ec))
      throw InputError(file,
                       file_parameter,
                       "no such file; expected a gmsh .msh mesh");
    if (!fs::is_regular_file(file, ec) || ::access(file.c_str(), R_OK) != 0)
      throw InputError(file,
                       file_parameter,
                       "not a readable file; expected a gmsh .msh mesh");

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
                  file_parameter,
                  "node " + std::to_string(node_tags[n]) +
                    " has a coordinate that is not a finite number");
            index[node_tags[n]] = n;
            result.vertices.emplace_back(coordinates[3 * n] * length_unit,
                                         coordinates[3 * n + 1] * length_unit,
                                         coordinates[3 * n + 2] * length_unit);
          }

        gmsh::vectorpair entities;
        gmsh::model::getEntities(entities, 3);
        for (const auto &[dim, entity] : entities)
          {
            // The label: the entity's physical group, or its own tag.
            std::vector<int> physical;
            gmsh::model::getPhysicalGroupsForEntity(dim, entity, physical);
            const int label = physical.empty() ? entity : physical[0];
            if (label < 0 || label > 65535)
              throw InputError(file,
                               file_parameter,
                               "volume tag " + std::to_string(label) +
                                 " is not a valid label; expected 0..65535");

            std::vector<int>                      types;
            std::vector<std::vector<std::size_t>> element_tags, element_nodes;
            gmsh::model::mesh::getElements(
              types, element_tags, element_nodes, dim, entity);
            for (unsigned int t = 0; t < types.size(); ++t)
              {
                if (types[t] != 4 && types[t] != 5)
                  throw InputError(file,
                                   file_parameter,
                                   "the mesh has 3d elements of gmsh type " +
                                     std::to_string(types[t]) +
                                     "; expected only linear tetrahedra (4) or "
                                     "hexahedra (5)");
                const unsigned int n = (types[t] == 4 ? 4 : 8);
                // gmsh numbers hexahedron vertices counter-clockwise per face.
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
                            file_parameter,
                            "element " + std::to_string(element_tags[t][e]) +
                              " refers to a node that does not exist");
                        cell.vertices[v] = it->second;
                      }
                    cell.material_id = label;
                    result.cells.push_back(cell);
                  }
              }
          }
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
                         file_parameter,
                         "not a valid gmsh mesh (" +
                           (message.empty() ? std::string("unreadable") :
                                              message) +
                           "); expected a gmsh .msh file with 3d cells");
      }
    gmsh::finalize();

    if (result.cells.empty())
      throw InputError(file, file_parameter, "the mesh has no 3d cells");
    const std::size_t n_vertices_per_cell = result.cells[0].vertices.size();
    for (const auto &cell : result.cells)
      if (cell.vertices.size() != n_vertices_per_cell)
        throw InputError(file,
                         file_parameter,
                         "the mesh mixes tetrahedra and hexahedra; expected "
                         "only one cell type");

    // Drop vertices that no cell uses (e.g. of boundary-only entities).
    std::vector<unsigned int> all(result.cells.size());
    std::iota(all.begin(), all.end(), 0u);
    result = select_cells(result, all);
    return result;
  }

  void
  write_gmsh(const MeshDescription &mesh,
             const double           length_unit,
             const std::string     &file)
  {
    Triangulation<3> tria;
    tria.create_triangulation(mesh.vertices, mesh.cells, SubCellData());
    write_gmsh(
      tria,
      [&](const unsigned int v) { return tria.get_vertices()[v]; },
      length_unit,
      file);
  }

  void
  write_gmsh(const Triangulation<3>                      &tria,
             const std::function<Point<3>(unsigned int)> &position,
             const double                                 length_unit,
             const std::string                           &file)
  {
    std::vector<bool> used(tria.n_vertices(), false);
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        used[cell->vertex_index(v)] = true;

    write_file_atomically(
      file,
      [&](std::ostream &out) {
        out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
            << std::count(used.begin(), used.end(), true) << '\n'
            << std::setprecision(16);
        for (unsigned int v = 0; v < used.size(); ++v)
          if (used[v])
            {
              const Point<3> p = position(v) / length_unit;
              out << v + 1 << ' ' << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
            }
        out << "$EndNodes\n$Elements\n" << tria.n_active_cells() << '\n';
        // gmsh numbers hexahedron vertices counter-clockwise per face.
        static const unsigned int hex_order[8] = {0, 1, 3, 2, 4, 5, 7, 6};
        unsigned int              n            = 0;
        for (const auto &cell : tria.active_cell_iterators())
          {
            const bool tet = cell->reference_cell().is_simplex();
            out << ++n << (tet ? " 4 2 " : " 5 2 ") << cell->material_id()
                << ' ' << cell->material_id();
            for (unsigned int v = 0; v < cell->n_vertices(); ++v)
              out << ' ' << cell->vertex_index(tet ? v : hex_order[v]) + 1;
            out << '\n';
          }
        out << "$EndElements\n";
      },
      "Output/Directory");
  }
} // namespace RestShape
