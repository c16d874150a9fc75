// A tetrahedral mesh split among MPI ranks (parallel::fullydistributed).
#include <deal.II/grid/cell_id.h>

#include <restshape/mesh/distributed_tetrahedra.h>

#include <algorithm>
#include <limits>

namespace RestShape
{
  using namespace dealii;

  CellPartition::CellPartition(const std::size_t  n_cells,
                               const unsigned int n_ranks)
    : starts(n_ranks + 1)
  {
    for (unsigned int r = 0; r <= n_ranks; ++r)
      starts[r] = n_cells * r / n_ranks;
  }

  unsigned int
  CellPartition::owner(const std::size_t cell) const
  {
    return std::upper_bound(starts.begin(), starts.end(), cell) -
           starts.begin() - 1;
  }

  CellPartition
  CellPartition::refined() const
  {
    CellPartition fine;
    fine.starts = starts;
    for (std::size_t &s : fine.starts)
      s *= 8;
    return fine;
  }

  namespace
  {
    constexpr unsigned int no_vertex = std::numeric_limits<unsigned>::max();

    /// The cells of @p mesh that rank @p rank owns or that share a vertex
    /// with one of them, in the order of @p mesh.
    std::vector<unsigned int>
    relevant_cells(const MeshDescription &mesh,
                   const CellPartition   &partition,
                   const unsigned int     rank)
    {
      std::vector<bool> touched(mesh.vertices.size(), false);
      for (unsigned int c = 0; c < mesh.cells.size(); ++c)
        if (partition.owner(c) == rank)
          for (const unsigned int v : mesh.cells[c].vertices)
            touched[v] = true;
      std::vector<unsigned int> cells;
      for (unsigned int c = 0; c < mesh.cells.size(); ++c)
        if (std::any_of(mesh.cells[c].vertices.begin(),
                        mesh.cells[c].vertices.end(),
                        [&](const unsigned int v) { return touched[v]; }))
          cells.push_back(c);
      return cells;
    }

    /// The description of cell @p c owned by @p owner: straight (flat
    /// manifold) edges and faces, no multigrid levels.
    TriangulationDescription::CellData<3>
    cell_info(const unsigned int c, const unsigned int owner)
    {
      TriangulationDescription::CellData<3> info;
      info.id                 = CellId(c, 0, nullptr).template to_binary<3>();
      info.subdomain_id       = owner;
      info.level_subdomain_id = numbers::invalid_subdomain_id;
      info.manifold_id        = numbers::flat_manifold_id;
      info.manifold_line_ids.fill(numbers::flat_manifold_id);
      info.manifold_quad_ids.fill(numbers::flat_manifold_id);
      return info;
    }
  } // namespace

  LocalPart
  local_part(const MeshDescription &mesh,
             const CellPartition   &partition,
             const MPI_Comm         comm)
  {
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    const auto         cells = relevant_cells(mesh, partition, rank);

    LocalPart                 part;
    std::vector<unsigned int> local(mesh.vertices.size(), no_vertex);
    for (const unsigned int c : cells)
      for (const unsigned int v : mesh.cells[c].vertices)
        local[v] = 0;
    for (unsigned int v = 0; v < local.size(); ++v)
      if (local[v] == 0)
        {
          local[v] = part.global_vertices.size();
          part.global_vertices.push_back(v);
          part.description.coarse_cell_vertices.push_back(mesh.vertices[v]);
          if (!mesh.targets.empty())
            part.targets.push_back(mesh.targets[v]);
        }

    auto &d     = part.description;
    d.comm      = comm;
    d.settings  = TriangulationDescription::Settings::default_setting;
    d.smoothing = Triangulation<3>::none;
    d.cell_infos.resize(1);
    for (const unsigned int c : cells)
      {
        CellData<3> cell(mesh.cells[c].vertices.size());
        for (unsigned int k = 0; k < cell.vertices.size(); ++k)
          cell.vertices[k] = local[mesh.cells[c].vertices[k]];
        cell.material_id = mesh.cells[c].material_id;
        d.coarse_cells.push_back(std::move(cell));
        if (!mesh.mass_ratios.empty())
          part.mass_ratios.push_back(mesh.mass_ratios[c]);
        d.coarse_cell_index_to_coarse_cell_id.push_back(c);
        d.cell_infos[0].push_back(cell_info(c, partition.owner(c)));
      }
    return part;
  }

  namespace
  {
    /// Owned cells: id, label, mass ratio, 4 vertices.
    constexpr unsigned int cell_values = 7;

    /// The owned cells and their vertices (index, position, target) of
    /// @p part, as numbers.
    std::pair<std::vector<double>, std::vector<double>>
    pack(const RankPart &part)
    {
      std::vector<double> cells, vertices;
      std::vector<bool>   packed(part.tria.n_vertices(), false);
      for (const auto &cell : part.tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cells.push_back(cell->id().get_coarse_cell_id());
            cells.push_back(cell->material_id());
            cells.push_back(
              part.mass_ratios.empty() ? 0. : part.mass_ratios[cell->index()]);
            for (const unsigned int v : cell->vertex_indices())
              {
                const unsigned int i = cell->vertex_index(v);
                cells.push_back(part.global_vertices[i]);
                if (packed[i])
                  continue;
                packed[i] = true;
                vertices.push_back(part.global_vertices[i]);
                for (unsigned int c = 0; c < 3; ++c)
                  vertices.push_back(part.positions[i][c]);
                for (unsigned int c = 0; c < 3 && !part.targets.empty(); ++c)
                  vertices.push_back(part.targets[i][c]);
              }
          }
      return {cells, vertices};
    }
  } // namespace

  MeshDescription
  gather_mesh(const RankPart &part, const unsigned int root)
  {
    const MPI_Comm comm    = part.tria.get_communicator();
    auto [cells, vertices] = pack(part);
    const bool all         = root == numbers::invalid_unsigned_int;
    const auto gather      = [&](const std::vector<double> &v) {
      return all ? Utilities::MPI::all_gather(comm, v) :
                        Utilities::MPI::gather(comm, v, root);
    };
    const std::vector<std::vector<double>> all_cells    = gather(cells);
    const std::vector<std::vector<double>> all_vertices = gather(vertices);
    MeshDescription                        mesh;
    if (!all && Utilities::MPI::this_mpi_process(comm) != root)
      return mesh;

    const bool         targets  = !part.targets.empty();
    const unsigned int per_node = targets ? 7 : 4;
    mesh.vertices.resize(part.n_vertices);
    if (targets)
      mesh.targets.resize(part.n_vertices);
    for (const auto &from : all_vertices)
      for (std::size_t k = 0; k < from.size(); k += per_node)
        {
          const auto v     = static_cast<std::size_t>(from[k]);
          mesh.vertices[v] = Point<3>(from[k + 1], from[k + 2], from[k + 3]);
          if (targets)
            mesh.targets[v] = Point<3>(from[k + 4], from[k + 5], from[k + 6]);
        }
    std::size_t n_cells = 0;
    for (const auto &from : all_cells)
      n_cells += from.size() / cell_values;
    mesh.cells.resize(n_cells, CellData<3>(4));
    if (!part.mass_ratios.empty())
      mesh.mass_ratios.resize(n_cells);
    for (const auto &from : all_cells)
      for (std::size_t k = 0; k < from.size(); k += cell_values)
        {
          const auto   c    = static_cast<std::size_t>(from[k]);
          CellData<3> &cell = mesh.cells[c];
          cell.material_id  = static_cast<types::material_id>(from[k + 1]);
          if (!mesh.mass_ratios.empty())
            mesh.mass_ratios[c] = from[k + 2];
          for (unsigned int v = 0; v < 4; ++v)
            cell.vertices[v] = static_cast<unsigned int>(from[k + 3 + v]);
        }
    return mesh;
  }
} // namespace RestShape
