#include <deal.II/base/mpi.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/mpi_reductions.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/fem/element_limits.h>
#include <restshape/loads/surface_pressure.h>

#include <array>
#include <cctype>
#include <limits>
#include <map>

namespace RestShape
{
  using namespace dealii;

  const std::string SurfacePressure::cavity_walls_name = "cavity walls";

  LoadTermInfo
  SurfacePressure::info()
  {
    LoadTermInfo i;
    i.name = "Surface pressure";
    i.description =
      "The pressure on the outer faces of Loads/Pressure labels: a uniform "
      "pressure (Loads/Surface pressure, e.g. the CSF's) and, with "
      "Loads/Fluid load = hydrostatic pressure, the immersing fluid's "
      "hydrostatic pressure below its level; a follower load on the current "
      "surface (with its exact tangent and, where the loaded surface is "
      "closed or held, its potential) or a dead load on the mesh's faces. "
      "In a scenario the faces of an opening of the skull lose it.";
    i.loads   = {SurfaceLoad::pressure_name,
                 SurfaceLoad::fluid_name,
                 SurfaceLoad::opening_pressure_name,
                 SurfaceLoad::opening_fluid_name};
    i.declare = [](ParameterHandler &prm) {
      prm.enter_subsection("Loads");
      prm.declare_entry("Surface pressure",
                        "0",
                        Patterns::Double(),
                        "Uniform pressure in Pa on the outer surface (e.g. "
                        "CSF), along the inward normal of the faces; see "
                        "Pressure load.");
      prm.declare_entry(
        "Pressure load",
        "follower",
        Patterns::Selection("follower|dead"),
        "follower: the pressure acts on the current (deformed) surface along "
        "its current normal, in every solve (a fluid's pressure; Newton uses "
        "its exact tangent). dead: the same tractions fixed on the faces of "
        "Mesh/File, whatever the body does (right only where the equilibrium "
        "is the mesh geometry itself).");
      prm.declare_entry("Pressure labels",
                        "",
                        Patterns::Anything(),
                        "The pressure acts on the outer faces of cells with "
                        "these labels; empty: all labels that are not fully "
                        "fixed.");
      prm.leave_subsection();
    };
    i.parse = [](ParameterHandler &prm, const double length_unit) {
      Settings s;
      prm.enter_subsection("Loads");
      s.pressure = prm.get_double("Surface pressure");
      s.follower = prm.get("Pressure load") == "follower";
      s.labels =
        parse_label_set(prm.get("Pressure labels"), "Loads/Pressure labels");
      prm.leave_subsection();
      EnvironmentParameters environment;
      environment.parse_parameters(prm, length_unit);
      return LoadTermFactory([s, environment](const LoadContext &context) {
        return std::make_unique<SurfacePressure>(s, environment, context);
      });
    };
    i.labels           = {{"Loads", "Pressure labels", false}};
    i.scenario_entries = {
      {SurfaceLoad::pressure_name,
       "",
       "The uniform surface pressure in Pa on the Loads/Pressure labels "
       "after the change (0: atmospheric, as in an opened skull). Empty: "
       "unchanged.",
       1}};
    return i;
  }

  SurfacePressure::SurfacePressure(const Settings              &settings,
                                   const EnvironmentParameters &environment,
                                   const LoadContext           &context)
    : SurfacePressure(settings,
                      environment,
                      context,
                      PressureNames(),
                      Walls::outer_and_cavities)
  {}

  SurfacePressure::SurfacePressure(const Settings              &settings,
                                   const EnvironmentParameters &environment,
                                   const LoadContext           &context,
                                   const PressureNames         &names,
                                   const Walls                  walls)
    : names(names)
    , settings(settings)
    , environment(environment)
    , context(context)
    , walls(walls == Walls::outer_and_cavities &&
                context.claimed_surfaces->count(cavity_walls_name) > 0 ?
              Walls::outer :
              walls)
    , labels(context.labels_or_unfixed(settings.labels))
  {
    if (this->walls != Walls::outer_and_cavities)
      cavities = std::make_unique<const CavityWalls>(context.mesh);
    const EnvironmentParameters &loads = environment;
    FEFaceValues<3>              fv(context.mapping,
                       context.fe,
                       context.face_quadrature,
                       update_quadrature_points);
    for_each_face([&](const auto &cell, auto f) {
      fv.reinit(cell, f);
      for (const Point<3> &x : fv.get_quadrature_points())
        points.push_back(x);
    });
    const Point<3> level =
      loads.has_fluid_level ? loads.fluid_level : highest_point(loads.gravity);
    load = std::make_unique<SurfaceLoad>(
      settings.follower, loads.hydrostatic ? loads.fluid_density : 0., level);
    if (loads.hydrostatic && loads.has_fluid_level && loads.gravity.norm() > 0)
      check_level_wets(level);

    // (A scenario may set a pressure where the scene has none.)
    bool pressure_acts =
      settings.pressure != 0 || (loads.hydrostatic && loads.gravity.norm() > 0);
    pressure_acts |= context.set_later.count(names.pressure) > 0;
    is_symmetric    = !(settings.follower && pressure_acts) || closed_or_held();
    scene_symmetric = is_symmetric;
  }

  void
  SurfacePressure::check_level_wets(const Point<3> &level) const
  {
    const Tensor<1, 3> up = -environment.gravity;
    // The deepest pressure-face point below the level (m; < 0: above).
    double deepest = -std::numeric_limits<double>::max();
    for (const Point<3> &x : points)
      deepest = std::max(deepest, -(up * (x - level)) / up.norm());
    deepest = Utilities::MPI::max(deepest, context.comm);
    if (!(deepest > 0))
      throw InputError(
        "",
        "Loads/Fluid level",
        "no pressure face lies below the fluid level (the lowest face "
        "point is " +
          number_text(-deepest / context.mesh.length_unit()) +
          " mesh units above it): the fluid wets nothing; expected a "
          "level above some of the pressure faces");
  }

  Point<3>
  SurfacePressure::highest_point(const Tensor<1, 3> &acceleration) const
  {
    const Tensor<1, 3> up      = -acceleration;
    double             highest = -std::numeric_limits<double>::max();
    Point<3>           top;
    for (const Point<3> &x : points)
      if (up * x > highest)
        {
          highest = up * x;
          top     = x;
        }
    // The highest point over all ranks.
    return largest_with_place(highest, top, context.comm).second;
  }

  void
  SurfacePressure::scene_load(LoadState &state) const
  {
    if (settings.pressure != 0)
      state.add(names.pressure, {settings.pressure});
    if (!names.fluid.empty())
      state.set(names.fluid,
                load->fluid_columns(environment.gravity, load->level));
  }

  void
  SurfacePressure::change_load(const ScenarioChange &change,
                               LoadState            &state) const
  {
    if (environment.hydrostatic && (change.turned || change.has_fluid_level))
      {
        // The fluid's pressure turns with gravity, about its level.
        const Tensor<1, 3> a = change.rotation * environment.gravity;
        const Point<3>     level =
          change.has_fluid_level      ? change.fluid_level :
              environment.has_fluid_level ? environment.fluid_level :
                                            highest_point(a);
        state.set(names.fluid, load->fluid_columns(a, level));
      }
    if (change.has(names.pressure))
      state.set(names.pressure, {{{change.value(names.pressure)}, 1.}});
  }

  void
  SurfacePressure::open_load(const ScenarioChange &change,
                             LoadState            &state) const
  {
    // The opening is at atmospheric pressure: its faces lose the pressure
    // that acts after the change.
    if (!change.opening.defined() || names.opening_pressure.empty())
      return;
    state.set(names.opening_pressure, state.columns(names.pressure));
    state.set(names.opening_fluid, state.columns(names.fluid));
  }

  std::string
  SurfacePressure::change_text(const LoadState &scene,
                               const LoadState &changed) const
  {
    const double before = scene.weighted(names.pressure),
                 after  = changed.weighted(names.pressure);
    if (before == after)
      return "";
    std::string what = names.pressure;
    what[0]          = std::tolower(what[0]);
    return what + " " + number_text(before) + " -> " + number_text(after) +
           " Pa";
  }

  unsigned int
  SurfacePressure::open(const Region &region)
  {
    opening = region;
    if (!opening.defined())
      {
        is_symmetric = scene_symmetric;
        return 0;
      }
    unsigned int faces = 0;
    for_each_face([&](const auto &cell, auto f) {
      faces += opening.contains(cell->face(f)->center());
    });
    faces = Utilities::MPI::sum(faces, context.comm);
    // The pressure jumps at the opening's rim, which nothing holds.
    if (faces > 0 && settings.follower)
      is_symmetric = false;
    return faces;
  }

  SurfaceLoad::Face
  SurfacePressure::face_kind(const CellIterator &cell,
                             const unsigned int  f) const
  {
    return opening.defined() && opening.contains(cell->face(f)->center()) ?
             SurfaceLoad::Face::opened :
             SurfaceLoad::Face::covered;
  }

  bool
  SurfacePressure::closed_or_held() const
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
    for_each_face(
      [&](const auto &cell, auto f) {
        for_each_edge(cell->face(f),
                      [&](const auto &line) { ++count[key(line)]; });
      },
      true);
    bool                                 held = true;
    std::vector<types::global_dof_index> dofs;
    const FESystem<3>                   &fe = context.fe;
    for_each_face([&](const auto &cell, auto f) {
      for_each_edge(cell->face(f), [&](const auto &line) {
        if (count[key(line)] != 1)
          return;
        dofs.resize(fe.n_dofs_per_line() + 2 * fe.n_dofs_per_vertex());
        line->get_dof_indices(dofs);
        for (const auto dof : dofs)
          held = held && context.is_held(dof);
      });
    });
    return Utilities::MPI::min(held ? 1 : 0, context.comm) == 1;
  }

  void
  SurfacePressure::assemble_faces(const LoadCell &c) const
  {
    if (!c.cell->at_boundary() || !labels.count(c.cell->material_id()))
      return;
    // The load's pressure once per surface cell.
    const PressureField field = SurfaceLoad::field(c.load, names);
    if (!load->acts(field))
      return;
    const bool          follower = load->follower();
    const FESystem<3>  &fe       = context.fe;
    const unsigned int  n_dofs   = fe.n_dofs_per_cell();
    FullMatrix<double> &K        = c.scratch.face_matrix;
    bool                any_face = false;
    for (const unsigned int f : c.cell->face_indices())
      {
        if (!c.cell->face(f)->at_boundary() || !on_walls(*c.cell, f))
          continue;
        if (c.matrix && follower && !any_face)
          K = 0;
        any_face              = true;
        const FaceScratch &fv = c.face(f);
        // An opening of the skull: its faces lose the opening's pressure.
        const SurfaceLoad::Face face = face_kind(c.cell, f);
        if (follower)
          {
            for (const unsigned int q : fv.quadrature_point_indices())
              add_follower(c, field, q, face);
            continue;
          }
        // Dead: -p(X) N dA on the face of the mesh geometry.
        for (const unsigned int q : fv.quadrature_point_indices())
          {
            const Tensor<1, 3> t =
              -load->pressure(field, fv.quadrature_point(q), face) *
              fv.normal_vector(q);
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const double f_ext = fv.shape_value(i, q) *
                                     t[fe.system_to_component_index(i).first] *
                                     fv.JxW(q);
                c.cell_external(i) += f_ext;
                c.cell_rhs(i) += f_ext;
              }
          }
      }
    if (!(c.matrix && follower && any_face))
      return;
    // Where the load is conservative its assembled tangent is symmetric,
    // and so is the sum of the faces' symmetric parts: the exact tangent
    // for the symmetric solvers.
    double *const       cell = &c.cell_matrix(0, 0);
    const double *const face = &K(0, 0);
    if (!is_symmetric)
      {
        for (unsigned int i = 0; i < n_dofs * n_dofs; ++i)
          cell[i] += face[i];
        return;
      }
    for (unsigned int i = 0; i < n_dofs; ++i)
      for (unsigned int j = 0; j < n_dofs; ++j)
        cell[i * n_dofs + j] +=
          0.5 * (face[i * n_dofs + j] + face[j * n_dofs + i]);
  }

  void
  SurfacePressure::add_follower(const LoadCell         &c,
                                const PressureField    &field,
                                const unsigned int      q,
                                const SurfaceLoad::Face face) const
  {
    const FESystem<3>  &fe     = context.fe;
    const unsigned int  n_dofs = fe.n_dofs_per_cell();
    FaceScratch        &s      = c.scratch;
    const FaceScratch  &fv     = s;
    const Tensor2       I      = unit_symmetric_tensor<3>();
    const Point<3>     &X      = fv.quadrature_point(q);
    const Tensor<1, 3> &N      = fv.normal_vector(q);
    const double        dA     = fv.JxW(q);
    // Follower: -p(x) cof(F) N dA on the current face, x = X + d.
    const Tensor2      F = I + s.face_grad_d[q];
    const Point<3>     x = X + s.face_d[q];
    const double       p = load->pressure(field, x, face);
    const Tensor<1, 3> a = cofactor_times(F, N) * dA;
    // Potential from the rest shape: Q . a now, less at X + w.
    const Tensor2 G = I + s.face_grad_w[q];
    c.energy += load->potential_flux(field, x, face) * a -
                load->potential_flux(field, X + s.face_w[q], face) *
                  cofactor_times(G, N) * dA;
    const std::vector<unsigned int> &component = c.d.components();
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        const double f_ext = -p * fv.shape_value(i, q) * a[component[i]];
        c.cell_external(i) += f_ext;
        c.cell_rhs(i) += f_ext;
      }
    if (!c.matrix)
      return;
    // K_ij = -d f_i / d u_j = phi_i (dp_j a + p da_j)[c_i], with
    // da_j = e_cj x (F (N x grad phi_j)) dA (cofactor_derivative): the
    // product F (N x g) once per scalar function, the rows only of the
    // shape functions that do not vanish at the point (those of the face).
    // Each entry gets one product per point, as before the loops were
    // turned: the same sums.
    const Tensor<1, 3> grad_p = load->pressure_gradient(field, x, face);
    const std::vector<unsigned int> &scalar   = c.d.scalar_functions();
    const unsigned int               n_scalar = fv.n_scalar_functions();
    // Plain arrays: a Tensor's constructor zeroes it, and these are written
    // whole before they are read.
    double phi[max_scalar_functions];
    double h[max_scalar_functions][3];
    AssertThrow(n_scalar <= max_scalar_functions, ExcInternalError());
    for (unsigned int k = 0; k < n_scalar; ++k)
      {
        phi[k] = fv.scalar_shape_value(k, q);
        const Tensor<1, 3> h_k =
          F * cross_product_3d(N, fv.scalar_shape_grad(k, q));
        for (unsigned int d = 0; d < 3; ++d)
          h[k][d] = h_k[d];
      }
    // The traction's derivative by each shape function j, by component:
    // grad_p[c_j] phi_j a + p (e_cj x h_j) dA, whose cross product has the
    // components 0, -h[c_j + 2] and h[c_j + 1] (indices mod 3) at c_j,
    // c_j + 1 and c_j + 2.
    std::array<std::array<double, 3 * max_scalar_functions>, 3> dt;
    for (unsigned int j = 0; j < n_dofs; ++j)
      {
        const unsigned int  cj = component[j];
        const unsigned int  c1 = (cj + 1) % 3, c2 = (cj + 2) % 3;
        const double *const hj = h[scalar[j]];
        const double        s  = grad_p[cj] * phi[scalar[j]];
        dt[cj][j]              = s * a[cj];
        dt[c1][j]              = s * a[c1] + (p * -hj[c2]) * dA;
        dt[c2][j]              = s * a[c2] + (p * hj[c1]) * dA;
      }
    // Each row of a function that does not vanish at the point: one
    // contiguous sum over the columns.
    double *const matrix = &s.face_matrix(0, 0);
    for (unsigned int i = 0; i < n_dofs; ++i)
      if (const double phi_i = phi[scalar[i]]; phi_i != 0)
        {
          double *const       row    = matrix + i * n_dofs;
          const double *const by_dof = dt[component[i]].data();
          for (unsigned int j = 0; j < n_dofs; ++j)
            row[j] += phi_i * by_dof[j];
        }
  }

  Tensor<1, 3>
  SurfacePressure::local_resultant(const LoadState  &state,
                                   const VectorType &d,
                                   const VectorType &) const
  {
    Tensor<1, 3>        force;
    const PressureField field = SurfaceLoad::field(state, names);
    if (!load->acts(field))
      return force;
    const bool                       follower   = load->follower();
    const Quadrature<2>             &quadrature = context.face_quadrature;
    FEFaceValues<3>                  ffv(context.mapping,
                        context.fe,
                        quadrature,
                        update_values | update_gradients |
                          update_quadrature_points | update_normal_vectors |
                          update_JxW_values);
    const FEValuesExtractors::Vector u(0);
    std::vector<Tensor<1, 3>>        face_d(quadrature.size());
    std::vector<Tensor2>             grad_d(quadrature.size());
    const Tensor2                    I = unit_symmetric_tensor<3>();
    for_each_face([&](const auto &cell, auto f) {
      ffv.reinit(cell, f);
      const SurfaceLoad::Face face = face_kind(cell, f);
      ffv[u].get_function_values(d, face_d);
      ffv[u].get_function_gradients(d, grad_d);
      for (const unsigned int q : ffv.quadrature_point_indices())
        {
          const Point<3>     &X = ffv.quadrature_point(q);
          const Tensor<1, 3> &N = ffv.normal_vector(q);
          force -= follower ? load->pressure(field, X + face_d[q], face) *
                                cofactor_times(I + grad_d[q], N) * ffv.JxW(q) :
                              load->pressure(field, X, face) * N * ffv.JxW(q);
        }
    });
    return force;
  }
} // namespace RestShape
