#include <deal.II/base/utilities.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_tools.h>

#include <gmsh.h>
#include <restshape/atomic_file.h>
#include <restshape/input_error.h>
#include <restshape/mesh.h>
#include <restshape/mesh_pieces.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <numeric>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    const std::string file_parameter = "Mesh/File";

    double
    triple_product(const Tensor<1, 3> &a,
                   const Tensor<1, 3> &b,
                   const Tensor<1, 3> &c)
    {
      return cross_product_3d(a, b) * c;
    }

    /**
     * Signed volume measure at every corner of a cell (tetrahedron: one
     * value; hexahedron: the eight corner Jacobian determinants), and the
     * longest edge, for the orientation check.
     */
    std::vector<double>
    corner_determinants(const std::vector<Point<3>> &v,
                        const CellData<3>           &cell,
                        double                      &longest_edge)
    {
      const auto         &i = cell.vertices;
      std::vector<double> dets;
      longest_edge = 0;
      for (unsigned int a = 0; a < i.size(); ++a)
        for (unsigned int b = a + 1; b < i.size(); ++b)
          longest_edge = std::max(longest_edge, v[i[a]].distance(v[i[b]]));
      if (i.size() == 4)
        dets.push_back(triple_product(v[i[1]] - v[i[0]],
                                      v[i[2]] - v[i[0]],
                                      v[i[3]] - v[i[0]]));
      else
        for (unsigned int corner = 0; corner < 8; ++corner)
          {
            // Edge vectors along the three reference directions, taken in
            // the positive direction whatever the corner.
            std::array<Tensor<1, 3>, 3> e;
            for (unsigned int d = 0; d < 3; ++d)
              {
                const unsigned int bit   = 1u << d;
                const unsigned int lower = corner & ~bit;
                e[d]                     = v[i[lower | bit]] - v[i[lower]];
              }
            dets.push_back(triple_product(e[0], e[1], e[2]));
          }
      return dets;
    }
  } // namespace

  Point<3>
  centroid(const std::vector<Point<3>>     &v,
           const std::vector<unsigned int> &indices)
  {
    Point<3> c;
    for (const unsigned int i : indices)
      c += v[i];
    return c / static_cast<double>(indices.size());
  }

  MeshDescription
  select_cells(const MeshDescription           &mesh,
               const std::vector<unsigned int> &cells)
  {
    MeshDescription result;
    result.cells.reserve(cells.size());
    const unsigned int        unused = numbers::invalid_unsigned_int;
    std::vector<unsigned int> new_index(mesh.vertices.size(), unused);
    for (const unsigned int c : cells)
      {
        CellData<3> cell = mesh.cells[c];
        for (unsigned int &v : cell.vertices)
          {
            if (new_index[v] == unused)
              {
                new_index[v] = result.vertices.size();
                result.vertices.push_back(mesh.vertices[v]);
              }
            v = new_index[v];
          }
        result.cells.push_back(cell);
      }
    return result;
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
  check_mesh(const MeshDescription &mesh, const std::string &file)
  {
    for (unsigned int v = 0; v < mesh.vertices.size(); ++v)
      for (unsigned int d = 0; d < 3; ++d)
        if (!std::isfinite(mesh.vertices[v][d]))
          throw InputError(file,
                           file_parameter,
                           "vertex " + std::to_string(v + 1) +
                             " has a coordinate that is not a finite number");

    unsigned int n_inverted = 0, n_degenerate = 0, first_bad = 0;
    for (unsigned int c = 0; c < mesh.cells.size(); ++c)
      {
        double     longest_edge = 0;
        const auto dets =
          corner_determinants(mesh.vertices, mesh.cells[c], longest_edge);
        const double scale    = std::pow(longest_edge, 3);
        bool         inverted = false, degenerate = !(longest_edge > 0);
        for (const double det : dets)
          {
            if (std::abs(det) <= 1e-12 * scale)
              degenerate = true;
            else if (det < 0)
              inverted = true;
          }
        if ((inverted || degenerate) && n_inverted + n_degenerate == 0)
          first_bad = c;
        n_inverted += (inverted && !degenerate);
        n_degenerate += degenerate;
      }
    if (n_inverted + n_degenerate > 0)
      throw InputError(file,
                       file_parameter,
                       std::to_string(n_inverted) + " inverted and " +
                         std::to_string(n_degenerate) +
                         " zero-volume cells (first: cell " +
                         std::to_string(first_bad + 1) +
                         " in file order); expected every cell with positive "
                         "volume in gmsh vertex order");
  }

  namespace
  {
    /// The midpoint vertex of every edge, created once.
    class EdgeMidpoints
    {
    public:
      EdgeMidpoints(std::vector<Point<3>> &vertices)
        : vertices(vertices)
      {}

      unsigned int
      operator()(const unsigned int a, const unsigned int b)
      {
        const std::array<unsigned int, 2> key{{std::min(a, b), std::max(a, b)}};
        const auto                        it = index.find(key);
        if (it != index.end())
          return it->second;
        vertices.push_back(0.5 * (vertices[a] + vertices[b]));
        return index[key] = vertices.size() - 1;
      }

    private:
      std::vector<Point<3>>                              &vertices;
      std::map<std::array<unsigned int, 2>, unsigned int> index;
    };

    /// A tetrahedron with positive orientation (two vertices swapped if
    /// needed).
    CellData<3>
    oriented_tet(const std::vector<Point<3>> &v,
                 std::array<unsigned int, 4>  t,
                 const types::material_id     label)
    {
      if (triple_product(v[t[1]] - v[t[0]],
                         v[t[2]] - v[t[0]],
                         v[t[3]] - v[t[0]]) < 0)
        std::swap(t[1], t[2]);
      CellData<3> cell(4);
      cell.vertices.assign(t.begin(), t.end());
      cell.material_id = label;
      return cell;
    }
  } // namespace

  MeshDescription
  refine_tetrahedra(const MeshDescription &tets)
  {
    MeshDescription fine;
    fine.vertices = tets.vertices;
    EdgeMidpoints midpoint(fine.vertices);
    for (const auto &tet : tets.cells)
      {
        const auto &t = tet.vertices;
        // m[i][j]: midpoint of edge (i, j).
        unsigned int m[4][4];
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = i + 1; j < 4; ++j)
            m[i][j] = m[j][i] = midpoint(t[i], t[j]);
        const auto &v = fine.vertices;
        for (unsigned int i = 0; i < 4; ++i)
          {
            std::array<unsigned int, 4> corner;
            for (unsigned int j = 0; j < 4; ++j)
              corner[j] = (i == j) ? t[i] : m[i][j];
            fine.cells.push_back(oriented_tet(v, corner, tet.material_id));
          }
        // The octahedron: diagonals join midpoints of opposite edges
        // (x y)-(z w); the equator around (x y)-(z w) is xz, xw, yw, yz.
        static const unsigned int diagonals[3][4] = {{0, 1, 2, 3},
                                                     {0, 2, 1, 3},
                                                     {0, 3, 1, 2}};
        unsigned int              best            = 0;
        double                    shortest = std::numeric_limits<double>::max();
        for (unsigned int k = 0; k < 3; ++k)
          {
            const auto  &d      = diagonals[k];
            const double length = v[m[d[0]][d[1]]].distance(v[m[d[2]][d[3]]]);
            if (length < shortest)
              {
                shortest = length;
                best     = k;
              }
          }
        const auto        &d = diagonals[best];
        const unsigned int x = d[0], y = d[1], z = d[2], w = d[3];
        const unsigned int equator[4] = {m[x][z], m[x][w], m[y][w], m[y][z]};
        for (unsigned int e = 0; e < 4; ++e)
          fine.cells.push_back(
            oriented_tet(v,
                         {{m[x][y], m[z][w], equator[e], equator[(e + 1) % 4]}},
                         tet.material_id));
      }
    return fine;
  }

  MeshDescription
  split_tetrahedra_into_hexahedra(const MeshDescription &tets)
  {
    // Vertices get a rank: 0 tet vertex, 1 edge midpoint, 2 face centroid,
    // 3 cell centroid. Every hexahedron is numbered so that each of its
    // edges runs from lower to higher rank, which orients all edges of the
    // mesh consistently (no reordering needed).
    MeshDescription                                     hexes;
    std::map<std::array<unsigned int, 2>, unsigned int> edge_vertex;
    std::map<std::array<unsigned int, 3>, unsigned int> face_vertex;
    hexes.vertices = tets.vertices;

    const auto new_vertex = [&](const std::vector<unsigned int> &of) {
      hexes.vertices.push_back(centroid(tets.vertices, of));
      return static_cast<unsigned int>(hexes.vertices.size() - 1);
    };
    const auto edge = [&](unsigned int a, unsigned int b) {
      std::array<unsigned int, 2> key{{std::min(a, b), std::max(a, b)}};
      const auto                  it = edge_vertex.find(key);
      if (it != edge_vertex.end())
        return it->second;
      return edge_vertex[key] = new_vertex({a, b});
    };
    const auto face = [&](unsigned int a, unsigned int b, unsigned int c) {
      std::array<unsigned int, 3> key{{a, b, c}};
      std::sort(key.begin(), key.end());
      const auto it = face_vertex.find(key);
      if (it != face_vertex.end())
        return it->second;
      return face_vertex[key] = new_vertex({a, b, c});
    };

    for (const auto &tet : tets.cells)
      {
        const auto        &t      = tet.vertices;
        const unsigned int center = new_vertex(t);
        for (unsigned int i = 0; i < 4; ++i)
          {
            std::array<unsigned int, 3> o;
            for (unsigned int k = 0, n = 0; k < 4; ++k)
              if (k != i)
                o[n++] = t[k];
            const Point<3> &p = tets.vertices[t[i]];
            if (triple_product(tets.vertices[o[0]] - p,
                               tets.vertices[o[1]] - p,
                               tets.vertices[o[2]] - p) < 0)
              std::swap(o[1], o[2]);

            CellData<3> hex(8);
            hex.vertices    = {t[i],
                               edge(t[i], o[0]),
                               edge(t[i], o[1]),
                               face(t[i], o[0], o[1]),
                               edge(t[i], o[2]),
                               face(t[i], o[0], o[2]),
                               face(t[i], o[1], o[2]),
                               center};
            hex.material_id = tet.material_id;
            hexes.cells.push_back(hex);
          }
      }
    return hexes;
  }

  void
  sort_along_hilbert_curve(MeshDescription &mesh)
  {
    std::vector<Point<3>> centroids;
    centroids.reserve(mesh.cells.size());
    for (const auto &cell : mesh.cells)
      centroids.push_back(centroid(mesh.vertices, cell.vertices));
    // 21 bits per coordinate: positions resolved to 1/2e6 of the bounding
    // box (about 0.1 micrometre for a brain).
    const auto curve =
      Utilities::inverse_Hilbert_space_filling_curve(centroids, 21);
    std::vector<std::uint64_t> key(curve.size());
    for (unsigned int c = 0; c < curve.size(); ++c)
      key[c] = Utilities::pack_integers<3>(curve[c], 21);
    std::vector<unsigned int> order(mesh.cells.size());
    std::iota(order.begin(), order.end(), 0u);
    // Grouped by label first: gmsh reads the cells of a file grouped by
    // entity (the label, in write_gmsh), and a rest_shape.msh must come
    // back in the order it was written.
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       const auto la = mesh.cells[a].material_id;
                       const auto lb = mesh.cells[b].material_id;
                       return la < lb || (la == lb && key[a] < key[b]);
                     });

    mesh = select_cells(mesh, order);
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

  LabelledMesh::LabelledMesh(const MeshParameters &prm, const MPI_Comm comm)
    : parameters(prm)
  {
    MeshDescription mesh = read_gmsh(prm.file, prm.length_unit);
    check_mesh(mesh, prm.file);
    // On the mesh as read (before any split into hexahedra).
    gap.first = std::numeric_limits<double>::infinity();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        const SurfaceGap g = narrowest_surface_gap(mesh, 0);
        gap                = {g.width, g.location};
      }
    sort_along_hilbert_curve(mesh);
    const bool file_is_tet = mesh.cells[0].vertices.size() == 4;
    if (prm.cell_type == CellType::tetrahedra && !file_is_tet)
      throw InputError(prm.file,
                       "Mesh/Cell type",
                       "the mesh has hexahedra; Cell type = tetrahedra needs "
                       "a tetrahedral mesh (use Cell type = hexahedra)");
    if (prm.cell_type == CellType::hexahedra && file_is_tet)
      {
        mesh = split_tetrahedra_into_hexahedra(mesh);
        check_mesh(mesh, prm.file);
      }

    const MeshPieces pieces = face_connected_pieces(mesh);
    if (pieces.n_cells.size() > 1 &&
        Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "Warning: " << prm.file << " (Mesh/File) has "
                << pieces.n_cells.size() << " pieces not joined by faces ("
                << pieces.n_cells[0] << " cells in the largest, "
                << pieces.n_cells.back()
                << " in the smallest). A piece held at a vertex or an edge "
                   "can rotate freely about it and stop Newton's method; "
                   "restshape-mesh removes small ones."
                << std::endl;
    for (const auto &cell : mesh.cells)
      ++counts[cell.material_id];
    const bool simplex = prm.cell_type == CellType::tetrahedra;
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      tria = std::make_unique<Triangulation<3>>();
    else if (simplex)
      tria = std::make_unique<parallel::shared::Triangulation<3>>(
        comm,
        Triangulation<3>::none,
        false,
        parallel::shared::Triangulation<3>::partition_metis);
    else
      tria = std::make_unique<parallel::distributed::Triangulation<3>>(comm);

    BoundingBox<3> box(mesh.vertices);
    bounding_diameter = box.get_boundary_points().first.distance(
      box.get_boundary_points().second);

    description = std::move(mesh);
    create_triangulation();
    for (unsigned int r = 0; r < prm.global_refinements; ++r)
      refine_global();
  }

  std::vector<Point<3>>
  LabelledMesh::read_rest_shape(const std::string &file) const
  {
    const std::string parameter = "Mesh/Rest shape file";
    MeshDescription   rest;
    try
      {
        rest = read_gmsh(file, parameters.length_unit);
        check_mesh(rest, file);
      }
    catch (const InputError &e)
      {
        throw InputError(file, parameter, e.message);
      }
    if (rest.cells.size() != tria->n_global_active_cells())
      throw InputError(
        file,
        parameter,
        "has " + std::to_string(rest.cells.size()) + " cells, the mesh " +
          std::to_string(tria->n_global_active_cells()) +
          "; expected the same cells in the same order (a rest_shape.msh "
          "written with the same Mesh settings)");
    std::vector<Point<3>> positions(tria->n_vertices());
    std::vector<bool>     set(tria->n_vertices(), false);
    const double          tolerance = 1e-9 * bounding_diameter;
    unsigned int          c         = 0;
    for (const auto &cell : tria->active_cell_iterators())
      {
        const auto &rest_cell = rest.cells[c++];
        if (rest_cell.vertices.size() != cell->n_vertices())
          throw InputError(file,
                           parameter,
                           "the cell types differ from the mesh's");
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          {
            const Point<3> &p = rest.vertices[rest_cell.vertices[v]];
            const auto      i = cell->vertex_index(v);
            if (set[i] && positions[i].distance(p) > tolerance)
              throw InputError(
                file,
                parameter,
                "its cells are not connected like the mesh's (cell " +
                  std::to_string(c) +
                  "); expected the same cells in the same order");
            positions[i] = p;
            set[i]       = true;
          }
      }
    return positions;
  }

  void
  LabelledMesh::create_triangulation()
  {
    tria->clear();
    tria->create_triangulation(description.vertices,
                               description.cells,
                               SubCellData());
    if (!is_simplex())
      description = MeshDescription(); // p4est/deal.II refine hexahedra
  }

  void
  LabelledMesh::refine_global(const std::function<void()> &before_change)
  {
    if (is_simplex())
      {
        if (before_change)
          before_change();
        description = refine_tetrahedra(description);
        create_triangulation();
        return;
      }
    tria->set_all_refine_flags();
    execute_refinement(before_change);
  }

  void
  LabelledMesh::execute_refinement(const std::function<void()> &before_change)
  {
    tria->prepare_coarsening_and_refinement();
    if (before_change)
      before_change();
    tria->execute_coarsening_and_refinement();
  }

  void
  LabelledMesh::refine_adaptive(const Vector<float>         &indicators,
                                const double                 refine_fraction,
                                const double                 coarsen_fraction,
                                const std::function<void()> &before_change)
  {
    Assert(!is_simplex(), ExcInternalError());
    // The rule of deal.II's serial GridRefinement::
    // refine_and_coarsen_fixed_number (refine the cells whose indicator is
    // at least the n-th largest, ties included; coarsen those at most the
    // m-th smallest), applied to the indicators of all ranks: the marked
    // cells do not depend on the number of ranks. (p4est's parallel
    // version finds its thresholds by bisection and breaks ties
    // differently: on the symmetric column it refined 72 cells where the
    // serial rule refines 136.)
    std::vector<float> owned;
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        owned.push_back(indicators[cell->active_cell_index()]);
    std::vector<float> all;
    for (const auto &part :
         Utilities::MPI::all_gather(tria->get_communicator(), owned))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end(), std::greater<float>());
    const auto n_refine =
      static_cast<std::size_t>(refine_fraction * all.size());
    const auto n_coarsen =
      static_cast<std::size_t>(coarsen_fraction * all.size());
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const float value = indicators[cell->active_cell_index()];
          if (n_refine > 0 && value >= all[n_refine - 1] && value > 0)
            cell->set_refine_flag();
          else if (n_coarsen > 0 && value <= all[all.size() - n_coarsen])
            cell->set_coarsen_flag();
        }
    execute_refinement(before_change);
  }

  Triangulation<3> &
  LabelledMesh::triangulation()
  {
    return *tria;
  }

  const Triangulation<3> &
  LabelledMesh::triangulation() const
  {
    return *tria;
  }

  bool
  LabelledMesh::is_simplex() const
  {
    return parameters.cell_type == CellType::tetrahedra;
  }

  const std::map<Label, unsigned int> &
  LabelledMesh::label_counts() const
  {
    return counts;
  }

  std::set<Label>
  LabelledMesh::labels() const
  {
    std::set<Label> result;
    for (const auto &[label, n] : counts)
      result.insert(label);
    return result;
  }

  std::pair<double, Point<3>>
  LabelledMesh::narrowest_gap() const
  {
    return gap;
  }

  double
  LabelledMesh::diameter() const
  {
    return bounding_diameter;
  }

  double
  LabelledMesh::minimum_cell_diameter() const
  {
    double h = std::numeric_limits<double>::max();
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        h = std::min(h, cell->diameter());
    return Utilities::MPI::min(h, tria->get_communicator());
  }
} // namespace RestShape
