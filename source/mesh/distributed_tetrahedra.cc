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
        }

    auto &d = part.description;
    d.comm  = comm;
    d.cell_infos.resize(1);
    for (const unsigned int c : cells)
      {
        CellData<3> cell(mesh.cells[c].vertices.size());
        for (unsigned int k = 0; k < cell.vertices.size(); ++k)
          cell.vertices[k] = local[mesh.cells[c].vertices[k]];
        cell.material_id = mesh.cells[c].material_id;
        d.coarse_cells.push_back(std::move(cell));
        d.coarse_cell_index_to_coarse_cell_id.push_back(c);
        d.cell_infos[0].push_back(cell_info(c, partition.owner(c)));
      }
    return part;
  }
} // namespace RestShape
