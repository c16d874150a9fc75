// Writing gmsh meshes (2.2 ASCII): cells, labels, boundary surfaces and
// the data of a rest shape.
#include <restshape/base/atomic_file.h>
#include <restshape/mesh/gmsh_io.h>

#include <algorithm>
#include <iomanip>
#include <map>
#include <set>

namespace RestShape
{
  using namespace dealii;

  namespace
  {

    /// The edge nodes of a quadratic rest shape: one per edge of its
    /// tetrahedra, numbered after the vertices.
    struct EdgeNodes
    {
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> of_edge;
      std::vector<Point<3>>                    position, target, equilibrium;
      std::vector<std::array<unsigned int, 6>> of_cell; // node indices
    };

    /// gmsh 2.2 node data @p name: @p value of every used vertex, then
    /// of the edge nodes @p edge_values.
    void
    write_node_data(std::ostream                                &out,
                    const std::string                           &name,
                    const std::vector<bool>                     &used,
                    const std::function<Point<3>(unsigned int)> &value,
                    const std::vector<Point<3>>                 &edge_values,
                    const double                                 length_unit)
    {
      out << "$NodeData\n1\n\"" << name << "\"\n1\n0\n3\n0\n3\n"
          << std::count(used.begin(), used.end(), true) + edge_values.size()
          << '\n';
      const auto write = [&](const std::size_t id, const Point<3> &x) {
        const Point<3> p = x / length_unit;
        out << id + 1 << ' ' << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      };
      for (unsigned int v = 0; v < used.size(); ++v)
        if (used[v])
          write(v, value(v));
      for (std::size_t e = 0; e < edge_values.size(); ++e)
        write(used.size() + e, edge_values[e]);
      out << "$EndNodeData\n";
    }

    /// gmsh 2.2 $NodeData/$ElementData of a rest shape.
    void
    write_rest_shape_data(std::ostream            &out,
                          const std::vector<bool> &used,
                          const RestShapeData     &rest,
                          const EdgeNodes         &edges,
                          const double             length_unit)
    {
      write_node_data(
        out, gmsh_target_view, used, rest.target, edges.target, length_unit);
      if (rest.equilibrium)
        write_node_data(out,
                        gmsh_equilibrium_view,
                        used,
                        rest.equilibrium,
                        edges.equilibrium,
                        length_unit);
      out << "$ElementData\n1\n\"" << gmsh_mass_ratio_view
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

    /// The edge nodes of @p rest's quadratic rest shape (none for a
    /// linear one) of the tetrahedra that @p cells visits.
    EdgeNodes
    number_edge_nodes(const CellVisitor &cells, const RestShapeData *rest)
    {
      EdgeNodes edges;
      if (rest == nullptr || rest->edge_nodes.empty())
        return edges;
      unsigned int c = 0;
      cells([&](Label, const std::vector<unsigned int> &v) {
        std::array<unsigned int, 6> ids;
        for (unsigned int k = 0; k < 6; ++k)
          {
            const unsigned int a = v[gmsh_tet10_edges[k][0]],
                               b = v[gmsh_tet10_edges[k][1]];
            const auto [it, added] =
              edges.of_edge.emplace(std::minmax(a, b), edges.position.size());
            ids[k] = it->second;
            if (!added)
              continue;
            edges.position.push_back(rest->edge_nodes[c][k]);
            edges.target.push_back(
              Point<3>((rest->target(a) + rest->target(b)) / 2));
            if (rest->equilibrium)
              edges.equilibrium.push_back(rest->edge_equilibria[c][k]);
          }
        edges.of_cell.push_back(ids);
        ++c;
      });
      return edges;
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
      const EdgeNodes edges = number_edge_nodes(cells, rest);
      write_file_atomically(
        file,
        [&](std::ostream &out) {
          out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
          write_physical_names(out, cells, names, surface_names);
          out << "$Nodes\n"
              << std::count(used.begin(), used.end(), true) +
                   edges.position.size()
              << '\n'
              << std::setprecision(16);
          const auto write_node = [&](const std::size_t id, const Point<3> &x) {
            const Point<3> p = x / length_unit;
            out << id + 1 << ' ' << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
          };
          for (unsigned int v = 0; v < used.size(); ++v)
            if (used[v])
              write_node(v, position(v));
          for (std::size_t e = 0; e < edges.position.size(); ++e)
            write_node(n_vertices + e, edges.position[e]);
          out << "$EndNodes\n$Elements\n" << n_cells + surfaces.size() << '\n';
          // gmsh numbers hexahedron vertices counter-clockwise per face.
          static const unsigned int hex_order[8] = {0, 1, 3, 2, 4, 5, 7, 6};
          unsigned int              n            = 0;
          cells([&](const Label label, const std::vector<unsigned int> &v) {
            const bool tet       = v.size() == 4;
            const bool quadratic = !edges.of_cell.empty();
            out << ++n
                << (quadratic ? " 11 2 " :
                    tet       ? " 4 2 " :
                                " 5 2 ")
                << label << ' ' << label;
            for (unsigned int k = 0; k < v.size(); ++k)
              out << ' ' << v[tet ? k : hex_order[k]] + 1;
            if (quadratic)
              for (const unsigned int e : edges.of_cell[n - 1])
                out << ' ' << n_vertices + e + 1;
            out << '\n';
          });
          for (const SurfaceTriangle &t : surfaces)
            out << ++n << " 2 2 " << t.tag << ' ' << t.tag << ' '
                << t.vertices[0] + 1 << ' ' << t.vertices[1] + 1 << ' '
                << t.vertices[2] + 1 << '\n';
          out << "$EndElements\n";
          if (rest != nullptr)
            write_rest_shape_data(out, used, *rest, edges, length_unit);
        },
        "Output/Directory");
    }
  } // namespace

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
