// LabelledMesh: the scene's triangulation, its labels and refinement.
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_tools.h>

#include <restshape/base/input_error.h>
#include <restshape/mesh/distributed_tetrahedra.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/labelled_mesh.h>
#include <restshape/mesh/mesh_checks.h>
#include <restshape/mesh/mesh_formats.h>
#include <restshape/mesh/mesh_pieces.h>
#include <restshape/mesh/mesh_transforms.h>

#include <algorithm>
#include <limits>

namespace RestShape
{
  using namespace dealii;

  LabelledMesh::LabelledMesh(const MeshParameters &prm,
                             const MPI_Comm        comm,
                             const SizeCheck      &check_size)
    : parameters(prm)
    , names(scene_label_names(prm))
  {
    MeshDescription mesh = read_mesh(prm.file, prm.length_unit);
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

    if (check_size)
      check_size(mesh.cells.size());

    const auto found =
      std::make_shared<MeshPieces>(face_connected_pieces(mesh));
    if (found->n_cells.size() > 1)
      {
        pieces      = found;
        pieces_mesh = std::make_shared<MeshDescription>(mesh);
      }
    if (found->n_cells.size() > 1 &&
        Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "Warning: " << prm.file << " (Mesh/File) has "
                << found->n_cells.size() << " pieces not joined by faces ("
                << found->n_cells[0] << " cells in the largest, "
                << found->n_cells.back()
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
      {
        // Each rank holds its cells and their neighbours only.
        tria =
          std::make_unique<parallel::fullydistributed::Triangulation<3>>(comm);
        partition = std::make_unique<CellPartition>(
          mesh.cells.size(), Utilities::MPI::n_mpi_processes(comm));
      }
    else
      tria = std::make_unique<parallel::distributed::Triangulation<3>>(comm);

    BoundingBox<3> box(mesh.vertices);
    bounding_diameter = box.get_boundary_points().first.distance(
      box.get_boundary_points().second);

    // Several ranks: refined before it is split (no rank would hold it all
    // again); one rank: the triangulation is refined.
    for (unsigned int r = 0; partition && r < prm.global_refinements; ++r)
      {
        mesh       = refine_tetrahedra(mesh);
        *partition = partition->refined();
      }
    create_triangulation(std::move(mesh));
    for (unsigned int r = 0; !partition && r < prm.global_refinements; ++r)
      refine_global();
  }

  std::vector<UnheldPiece>
  LabelledMesh::unheld_pieces(const std::set<Label> &held_labels) const
  {
    if (!pieces)
      return {};
    return RestShape::unheld_pieces(*pieces_mesh, *pieces, held_labels);
  }

  LabelNames
  scene_label_names(const MeshParameters &parameters)
  {
    LabelNames names = read_mesh_label_names(parameters.file);
    if (parameters.label_names_file.empty())
      return names;
    const std::string parameter = "Mesh/Label names";
    const LabelNames  table =
      read_label_names(parameters.label_names_file, parameter);
    for (const auto &[label, name] : table.by_label())
      names.add(label, name, parameters.label_names_file, parameter);
    return names;
  }

  const LabelNames &
  LabelledMesh::label_names() const
  {
    return names;
  }

  std::vector<Point<3>>
  LabelledMesh::read_rest_shape(const std::string &file) const
  {
    const std::string parameter = "Mesh/Rest shape file";
    MeshDescription   rest;
    try
      {
        rest = read_mesh(file, parameters.length_unit, parameter);
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
    for (const auto &cell : tria->active_cell_iterators())
      {
        const std::size_t c         = cell_index(*cell);
        const auto       &rest_cell = rest.cells[c];
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
  LabelledMesh::create_triangulation(MeshDescription &&mesh)
  {
    tria->clear();
    if (!partition)
      {
        tria->create_triangulation(mesh.vertices, mesh.cells, SubCellData());
        // Coarse cells keep the order of the description.
        mass_ratios    = std::move(mesh.mass_ratios);
        vertex_targets = std::move(mesh.targets);
        rest_nodes     = std::move(mesh.rest_nodes);
        return;
      }
    LocalPart part = local_part(mesh, *partition, tria->get_communicator());
    dynamic_cast<parallel::fullydistributed::Triangulation<3> &>(*tria)
      .create_triangulation(part.description);
    global_vertices  = std::move(part.global_vertices);
    n_whole_vertices = mesh.vertices.size();
    mass_ratios      = std::move(part.mass_ratios);
    vertex_targets   = std::move(part.targets);
    rest_nodes       = std::move(mesh.rest_nodes); // by position
    of_owned_cell.assign(tria->n_vertices(), false);
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          of_owned_cell[cell->vertex_index(v)] = true;
  }

  MeshDescription
  LabelledMesh::coarse_description() const
  {
    if (partition)
      return gather_mesh(RankPart{*tria,
                                  global_vertices,
                                  n_whole_vertices,
                                  tria->get_vertices(),
                                  vertex_targets,
                                  mass_ratios},
                         numbers::invalid_unsigned_int);
    MeshDescription mesh;
    mesh.vertices = tria->get_vertices();
    mesh.cells.reserve(tria->n_cells(0));
    for (const auto &cell : tria->cell_iterators_on_level(0))
      {
        CellData<3> data(cell->n_vertices());
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          data.vertices[v] = cell->vertex_index(v);
        data.material_id = cell->material_id();
        mesh.cells.push_back(std::move(data));
      }
    mesh.targets     = vertex_targets;
    mesh.mass_ratios = mass_ratios;
    return mesh;
  }

  void
  LabelledMesh::refine_global(const std::function<void()> &before_change)
  {
    if (is_simplex())
      {
        if (before_change)
          before_change();
        // Tetrahedra are rebuilt from the coarse cells (deal.II 9.4 does
        // not refine simplices in the tree); children stay on their
        // parent's rank.
        MeshDescription fine = refine_tetrahedra(coarse_description());
        if (partition)
          *partition = partition->refined();
        create_triangulation(std::move(fine));
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

  double
  LabelledMesh::mass_ratio(const CellAccessor<3, 3> &cell) const
  {
    if (mass_ratios.empty())
      return 1;
    // Tetrahedra: every cell is a coarse cell; hexahedra: the ancestor's.
    if (cell.level() == 0)
      return mass_ratios[cell.index()];
    auto ancestor = cell.parent();
    while (ancestor->level() > 0)
      ancestor = ancestor->parent();
    return mass_ratios[ancestor->index()];
  }

  bool
  LabelledMesh::at_surface(const CellAccessor<3, 3> &cell,
                           const unsigned int        f) const
  {
    const auto face = cell.face(f);
    if (!face->at_boundary())
      return false;
    if (!partition || cell.is_locally_owned())
      return true;
    // A face of a ghost cell whose neighbour this rank does not hold also
    // has no neighbour here; it has no vertex of an owned cell (else the
    // neighbour would share it and be a ghost).
    for (const unsigned int v : face->vertex_indices())
      if (of_owned_cell[face->vertex_index(v)])
        return true;
    return false;
  }

  std::size_t
  LabelledMesh::cell_index(const CellAccessor<3, 3> &cell) const
  {
    // Tetrahedra are coarse cells (refined by rebuilding the mesh).
    if (is_simplex())
      return cell.id().get_coarse_cell_id();
    return cell.active_cell_index();
  }

  void
  LabelledMesh::write_gmsh(const std::vector<Point<3>> &positions,
                           const std::string           &file,
                           const std::vector<double>   &rest_mass_ratios,
                           const RestNodes             &nodes) const
  {
    RestShapeData rest;
    rest.mass_ratios    = rest_mass_ratios;
    const MPI_Comm comm = tria->get_communicator();
    if (!partition)
      {
        const auto &vertices = tria->get_vertices();
        rest.target          = [&](const unsigned int v) {
          return vertex_targets.empty() ? vertices[v] : vertex_targets[v];
        };
        if (!nodes.equilibria.empty())
          rest.equilibrium = [&](const unsigned int v) {
            return nodes.equilibria[v];
          };
        rest.edge_nodes      = nodes.edge_rest;
        rest.edge_equilibria = nodes.edge_equilibria;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          RestShape::write_gmsh(
            *tria,
            [&](const unsigned int v) { return positions[v]; },
            parameters.length_unit,
            file,
            &rest,
            names);
        return;
      }
    // Rank 0 gathers the whole mesh at the positions; its targets are the
    // mesh's (or the vertices).
    const MeshDescription whole =
      gather_mesh(RankPart{*tria,
                           global_vertices,
                           n_whole_vertices,
                           positions,
                           vertex_targets.empty() ? tria->get_vertices() :
                                                    vertex_targets,
                           {}},
                  0);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    rest.target = [&](const unsigned int v) { return whole.targets[v]; };
    RestShape::write_gmsh(
      whole,
      [&](const unsigned int v) { return whole.vertices[v]; },
      parameters.length_unit,
      file,
      &rest,
      names);
  }

  const std::vector<Point<3>> &
  LabelledMesh::targets() const
  {
    return vertex_targets;
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
