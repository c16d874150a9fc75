// Tetrahedra on several ranks (source/mesh/distributed_tetrahedra.cc):
// each rank's triangulation holds its own cells and the cells that share a
// vertex with them, not the whole mesh. On the coarse brain (and once
// refined), checks that
// 1. every cell is owned by exactly one rank, and the owned cells of a
//    rank are the contiguous piece that CellPartition gives it;
// 2. a rank holds at most (1/N + 1/4) of the cells (on 1 rank: all);
// 3. LabelledMesh::cell_index() numbers the cells of the whole mesh: the
//    owned cells of all ranks together are 0 .. n - 1, each once;
// 4. after refine_global() the children of a cell stay on its rank and the
//    mesh has 8 times the cells;
// 5. the mesh's volume is the whole mesh's on any number of ranks;
// 6. the mesh written from the parts (LabelledMesh::write_gmsh(), rank 0
//    gathers it) is the file one rank writes, byte for byte.
// Runs on 1 and on 2 MPI ranks (tests/CMakeLists.txt).
#include <deal.II/base/mpi.h>

#include <restshape/base/mpi_start.h>
#include <restshape/mesh/labelled_mesh.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  /// Checks 1-3 and 5 on the current mesh; returns the owned cells' indices.
  std::vector<std::size_t>
  check_layout(const std::string  &name,
               const LabelledMesh &mesh,
               const double        expected_volume)
  {
    const MPI_Comm           comm  = MPI_COMM_WORLD;
    const unsigned int       ranks = Utilities::MPI::n_mpi_processes(comm);
    const auto              &tria  = mesh.triangulation();
    const std::size_t        n     = tria.n_global_active_cells();
    std::vector<std::size_t> owned;
    double                   volume = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          owned.push_back(mesh.cell_index(*cell));
          volume += cell->measure();
        }
    check_below(name + ": cells held by this rank / all cells - 1/N",
                static_cast<double>(tria.n_active_cells()) / n - 1. / ranks,
                ranks == 1 ? 0 : 0.25);
    std::vector<std::size_t> all;
    for (const auto &part : Utilities::MPI::all_gather(comm, owned))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    bool numbered = all.size() == n;
    for (std::size_t i = 0; numbered && i < n; ++i)
      numbered = all[i] == i;
    check_between(name + ": owned cells of all ranks are 0 .. n-1, once",
                  numbered,
                  1,
                  1);
    std::sort(owned.begin(), owned.end());
    check_between(name + ": the owned cells are contiguous",
                  owned.empty() ||
                    owned.back() - owned.front() + 1 == owned.size(),
                  1,
                  1);
    check_below(name + ": volume against the whole mesh's (relative)",
                std::abs(Utilities::MPI::sum(volume, comm) / expected_volume -
                         1),
                1e-12);
    return owned;
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Parameters                 parameters = parsed_parameters(
    "subsection Mesh\n set File = meshes/brain_coarse.msh\n set Length unit "
                    "= mm\n set Cell type = tetrahedra\nend\n");

  // Named by the number of ranks: the 1- and 2-rank tests run side by side.
  const auto file = [](const std::string &name) {
    return (std::filesystem::temp_directory_path() /
            (std::to_string(Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)) +
             "_" + name))
      .string();
  };
  const bool root   = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  double     volume = 0;
  {
    LabelledMesh reference(parameters.mesh, MPI_COMM_SELF);
    for (const auto &cell : reference.triangulation().active_cell_iterators())
      volume += cell->measure();
    if (root)
      reference.write_gmsh(reference.triangulation().get_vertices(),
                           file("restshape_serial.msh"),
                           {});
  }
  LabelledMesh      mesh(parameters.mesh, MPI_COMM_WORLD);
  const auto        coarse = check_layout("coarse brain", mesh, volume);
  const std::size_t n      = mesh.triangulation().n_global_active_cells();
  mesh.write_gmsh(mesh.triangulation().get_vertices(),
                  file("restshape_parts.msh"),
                  {});
  if (root)
    {
      const auto text = [](const std::string &name) {
        std::ifstream     in(name);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
      };
      const std::string serial = text(file("restshape_serial.msh"));
      check_between("the mesh written from the parts is one rank's file",
                    !serial.empty() &&
                      serial == text(file("restshape_parts.msh")),
                    1,
                    1);
    }
  mesh.refine_global();
  const auto fine = check_layout("refined once", mesh, volume);
  check_between("refined once: 8 times the cells",
                mesh.triangulation().n_global_active_cells(),
                8 * n,
                8 * n);
  bool children_stay = fine.size() == 8 * coarse.size();
  for (std::size_t i = 0; children_stay && i < fine.size(); ++i)
    children_stay = fine[i] / 8 == coarse[i / 8];
  check_between("refined once: the children stay on their parent's rank",
                children_stay,
                1,
                1);
  return exit_code();
}
