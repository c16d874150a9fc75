// ForwardProblem: the loads. The pressure faces and their free surface,
// the body force (gravity on the buoyed density, a force field on the
// tissue, the buoyancy lost where the fluid is drained), the scene's load.
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <restshape/base/input_error.h>
#include <restshape/base/mpi_reductions.h>
#include <restshape/forward/forward_problem.h>

#include <limits>

namespace RestShape
{
  using namespace dealii;

  void
  ForwardProblem::setup_surface_load()
  {
    const LoadParameters &loads = parameters.loads;
    // The pressure faces' quadrature points (mesh geometry).
    pressure_points.clear();
    FEFaceValues<3> fv(*mapping_,
                       fe_,
                       face_quadrature_,
                       update_quadrature_points);
    for_each_boundary_face(pressure_labels, [&](const auto &cell, auto f) {
      fv.reinit(cell, f);
      for (const Point<3> &x : fv.get_quadrature_points())
        pressure_points.push_back(x);
    });
    const Point<3> level = loads.has_fluid_level ?
                             loads.fluid_level :
                             highest_pressure_point(loads.gravity);
    surface_load_        = std::make_unique<SurfaceLoad>(loads, level);

    const Tensor<1, 3> up = -loads.gravity;
    if (loads.hydrostatic && loads.has_fluid_level && up.norm() > 0)
      {
        // The deepest pressure-face point below the level (m; < 0: above).
        double deepest = -std::numeric_limits<double>::max();
        for (const Point<3> &x : pressure_points)
          deepest = std::max(deepest, -(up * (x - level)) / up.norm());
        deepest = Utilities::MPI::max(deepest, comm);
        if (!(deepest > 0))
          throw InputError(
            "",
            "Loads/Fluid level",
            "no pressure face lies below the fluid level (the lowest face "
            "point is " +
              number_text(-deepest / parameters.mesh.length_unit) +
              " mesh units above it): the fluid wets nothing; expected a "
              "level above some of the pressure faces");
      }
    // (A scenario may set a pressure where the scene has none.)
    bool pressure_acts =
      loads.pressure != 0 || (loads.hydrostatic && loads.gravity.norm() > 0);
    for (const ScenarioParameters &scenario : parameters.scenarios)
      pressure_acts |= scenario.has_pressure && scenario.pressure != 0;
    symmetric_tangent = !(loads.follower && pressure_acts) ||
                        pressure_surface_is_closed_or_held();
    scene_tangent_symmetric = symmetric_tangent;
  }

  Point<3>
  ForwardProblem::highest_pressure_point(const Tensor<1, 3> &acceleration) const
  {
    const Tensor<1, 3> up      = -acceleration;
    double             highest = -std::numeric_limits<double>::max();
    Point<3>           top;
    for (const Point<3> &x : pressure_points)
      if (up * x > highest)
        {
          highest = up * x;
          top     = x;
        }
    // The highest point over all ranks.
    return largest_with_place(highest, top, comm).second;
  }

  unsigned int
  ForwardProblem::open_surface(const Region &region)
  {
    opening = region;
    if (!opening.defined())
      {
        symmetric_tangent = scene_tangent_symmetric;
        linear_solver->set_symmetric(symmetric_tangent);
        return 0;
      }
    unsigned int faces = 0;
    for_each_boundary_face(pressure_labels, [&](const auto &cell, auto f) {
      faces += opening.contains(cell->face(f)->center());
    });
    faces = Utilities::MPI::sum(faces, comm);
    // The pressure jumps at the opening's rim, which nothing holds.
    if (faces > 0 && parameters.loads.follower && symmetric_tangent)
      {
        symmetric_tangent = false;
        linear_solver->set_symmetric(false);
      }
    return faces;
  }

  bool
  ForwardProblem::pressure_surface_is_closed_or_held() const
  {
    // Edges (vertex pairs) of the pressure faces of owned and ghost cells,
    // with the number of pressure faces that share them: an edge of only
    // one is an edge of the loaded surface.
    // With hanging nodes, a coarse face's edge is refined on its finer
    // neighbour's side: its halves are the edges that count.
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> count;
    const auto key = [](const auto &line) {
      const unsigned int a = line->vertex_index(0), b = line->vertex_index(1);
      return std::make_pair(std::min(a, b), std::max(a, b));
    };
    const auto for_each_edge = [](const auto &face, const auto &f) {
      for (unsigned int l = 0; l < face->n_lines(); ++l)
        {
          const auto line = face->line(l);
          if (line->has_children())
            for (unsigned int c = 0; c < line->n_children(); ++c)
              f(line->child(c));
          else
            f(line);
        }
    };
    for_each_boundary_face(
      pressure_labels,
      [&](const auto &cell, auto f) {
        for_each_edge(cell->face(f),
                      [&](const auto &line) { ++count[key(line)]; });
      },
      true);
    bool                                 held = true;
    std::vector<types::global_dof_index> dofs;
    for_each_boundary_face(pressure_labels, [&](const auto &cell, auto f) {
      for_each_edge(cell->face(f), [&](const auto &line) {
        if (count[key(line)] != 1)
          return;
        dofs.resize(fe_.n_dofs_per_line() + 2 * fe_.n_dofs_per_vertex());
        line->get_dof_indices(dofs);
        for (const auto dof : dofs)
          held = held && is_held(dof);
      });
    });
    return Utilities::MPI::min(held ? 1 : 0, comm) == 1;
  }

  double
  ForwardProblem::effective_density(const CellAccessor<3, 3> &cell) const
  {
    const Label label = cell.material_id();
    return labelled_mesh.mass_ratio(cell) *
           (material_table.density(label) - (parameters.loads.hydrostatic ?
                                               0. :
                                               parameters.loads.fluid_density));
  }

  bool
  ForwardProblem::body_force_varies(const LoadState &load) const
  {
    return !parameters.loads.hydrostatic &&
           parameters.loads.fluid_density > 0 &&
           load.drained_acceleration.norm_square() > 0;
  }

  Tensor<1, 3>
  ForwardProblem::body_force(const CellAccessor<3, 3> &cell,
                             const Point<3>           &X,
                             const LoadState          &load) const
  {
    Tensor<1, 3> f      = effective_density(cell) * load.acceleration;
    const double tissue = labelled_mesh.mass_ratio(cell) *
                          material_table.density(cell.material_id());
    if (load.tissue_acceleration.norm_square() > 0)
      f += tissue * load.tissue_acceleration;
    // Above the free surface (against the drained acceleration) the
    // tissue has lost its buoyancy.
    if (body_force_varies(load) &&
        load.drained_acceleration * (X - load.fluid_level) < 0)
      f += labelled_mesh.mass_ratio(cell) * parameters.loads.fluid_density *
           load.drained_acceleration;
    return f;
  }

  LoadState
  ForwardProblem::scene_load() const
  {
    LoadState load;
    load.acceleration = parameters.loads.gravity;
    load.pressure     = parameters.loads.pressure;
    load.fluid        = surface_load_->scene_fluid(parameters.loads.gravity);
    return load;
  }
} // namespace RestShape
