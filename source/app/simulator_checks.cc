// The checks of a scene before and after its mesh is made: labels,
// supports, pieces, obstacle placement, load scales.
#include <restshape/app/scenario.h>
#include <restshape/app/simulator.h>
#include <restshape/base/input_error.h>
#include <restshape/base/units.h>
#include <restshape/contact/admissible_target.h>
#include <restshape/forward/load_scales.h>
#include <restshape/mesh/mesh_pieces.h>

#include <cmath>
#include <set>

namespace RestShape
{
  using namespace dealii;

  void
  Simulator::check_scene_on_mesh() const
  {
    for (const LabelList &list : parameters.label_lists)
      try
        {
          check_labels_exist(list, mesh->labels());
        }
      catch (const InputError &e)
        {
          throw e.in_file(prm_file);
        }
    if (parameters.refinement.strategy ==
          RefinementParameters::Strategy::adaptive &&
        mesh->is_simplex())
      throw InputError(
        prm_file,
        "Adaptive refinement/Strategy",
        "adaptive refinement needs hexahedra: deal.II 9.4 has no "
        "hanging-node constraints on tetrahedra; use Mesh/Cell type "
        "= hexahedra or Strategy = global");
    if (!parameters.mesh.rest_shape_file.empty() &&
        parameters.refinement.cycles > 0)
      throw InputError(
        prm_file,
        "Mesh/Rest shape file",
        "a rest shape file describes one mesh; expected Adaptive "
        "refinement/Cycles = 0 (use Mesh/Global refinements)");

    check_something_is_free();
    check_fixed_planes();
    if (!parameters.scenarios.empty())
      try
        {
          check_scenario(parameters, *mesh, comm);
        }
      catch (const InputError &e)
        {
          throw e.in_file(prm_file);
        }
  }

  void
  Simulator::check_something_is_free() const
  {
    for (const Label label : mesh->labels())
      if (!parameters.forward.discretization.fully_fixed(label))
        return;
    throw InputError(prm_file,
                     "Boundary conditions/Fixed labels",
                     "every label of the mesh (" + to_string(mesh->labels()) +
                       ") is fixed in all three directions: nothing is free "
                       "to move; expected at least one label that is not");
  }

  void
  Simulator::check_fixed_planes() const
  {
    for (const FixedPlane &plane :
         parameters.forward.discretization.fixed_planes)
      {
        unsigned int faces = 0;
        for (const auto &cell : mesh->triangulation().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              faces += cell->at_boundary(f) &&
                       plane.holds(*cell->face(f), mesh->length_unit());
        if (Utilities::MPI::sum(faces, comm) == 0)
          throw InputError(prm_file,
                           "Boundary conditions/Fixed boundary planes",
                           "no boundary face of the mesh lies in the plane " +
                             plane.text() +
                             " (coordinates in the mesh's length unit); "
                             "expected a plane that holds a face of the "
                             "surface, e.g. a symmetry plane of the mesh");
      }
  }

  void
  Simulator::check_scene_on_problem() const
  {
    if (parameters.forward.solver.check_stability == StabilityCheck::on &&
        !forward->loads().symmetric())
      throw InputError(
        prm_file,
        "Solver/Check stability",
        "the follower pressure acts on a surface with free edges, which is "
        "not conservative (its tangent is not symmetric): stability is "
        "then not a question of the energy; expected Check stability = "
        "false, or pressure faces that are closed or held at their edges");
    if (contact || forward->loads().has_support())
      return;
    // A piece that neither a fixed label nor a joint to a held piece holds
    // floats: its rigid motion makes the problem singular.
    for (const UnheldPiece &piece : mesh->unheld_pieces(held_labels()))
      if (piece.n_joints > 0)
        pcout << "Warning: "
              << piece.text(mm_per_m / parameters.mesh.length_unit)
              << ": only that joint holds it (no fixed label in it, no "
                 "contact or elastic support), so it turns about it without "
                 "resistance until the load holds it"
              << std::endl;
      else
        throw InputError(
          prm_file,
          "Mesh/File, Boundary conditions/Fixed labels",
          piece.text(mm_per_m / parameters.mesh.length_unit) +
            ", with no fixed label, contact or elastic support: the problem "
            "is singular (free rigid-body motion); expected each piece of "
            "the mesh fixed or joined by faces to a fixed one");
    // Without contact or elastic support, every displacement component must
    // be fixed somewhere, or rigid-body motion makes the problem singular.
    const std::array<bool, 3> held =
      forward->discretization().fixed_components();
    for (unsigned int c = 0; c < 3; ++c)
      if (!held[c])
        throw InputError(
          prm_file,
          "Boundary conditions/Fixed labels",
          std::string("no node is fixed in ") + "xyz"[c] +
            " and there is no contact or elastic support: the problem is singular "
            "(free rigid-body motion); expected fixed labels or fixed "
            "boundary planes that hold every component");
  }

  void
  Simulator::check_obstacle_placement() const
  {
    const std::vector<Point<3>> &targets = mesh->targets();
    if (targets.empty())
      {
        AdmissibleTarget(*contact).check_placement();
        return;
      }
    // A rest shape may cross the obstacle; its target may not.
    const auto               &vertices = mesh->triangulation().get_vertices();
    std::vector<Tensor<1, 3>> shift(vertices.size());
    for (unsigned int v = 0; v < targets.size(); ++v)
      shift[v] = targets[v] - vertices[v];
    const VectorType ghosted = forward->discretization().ghosted_copy(
      forward->discretization().interpolate_vertex_field(shift));
    AdmissibleTarget(*contact).check_placement(&ghosted);
  }

  void
  Simulator::report_load_scales() const
  {
    const LoadScales scales = compute_load_scales(*forward);
    // Loads or materials whose scale overflows double precision (gravity
    // 1e300, a density of 1e308) make every residual NaN.
    if (!std::isfinite(scales.mass) || !std::isfinite(scales.gravity_strain))
      throw InputError(prm_file,
                       "Loads/Gravity, Materials/Density",
                       "the strain of the weight, density x gravity x "
                       "height / Young's modulus, is not a finite number "
                       "(it overflows double precision); expected gravity "
                       "and densities whose product fits a double");
    if (!std::isfinite(scales.pressure_strain))
      throw InputError(prm_file,
                       "Loads/Surface pressure",
                       "the pressure's strain p / E is not a finite number; "
                       "expected a finite pressure");
    pcout << scales.text() << std::endl;
    for (const std::string &warning : scales.warnings())
      pcout << "Warning: " << warning << std::endl;
    const DiscretizationParameters &d = parameters.forward.discretization;
    if (!d.formulation_warning.empty())
      pcout << "Warning: " << d.formulation_warning << std::endl;
    if (d.mixed)
      pcout << "Formulation: mixed, "
            << (d.linear_cell_pressure ?
                  std::string("a pressure linear on each cell, "
                              "discontinuous across cells (Q2-P1disc)") :
                !d.nodal_pressure ?
                  std::string(
                    "a pressure constant per cell (its mean dilatation)") :
                  std::string("the averaged nodal pressure of linear "
                              "tetrahedra (boundary vertices: ") +
                    (d.boundary_shares_to_interior ? "interior" : "own") + ")")
            << std::endl;
    if (!d.formulation_note.empty())
      pcout << "Note: " << d.formulation_note << std::endl;
  }

  std::set<Label>
  Simulator::held_labels() const
  {
    std::set<Label> held;
    for (const auto &fixed : parameters.forward.discretization.fixed_labels)
      held.insert(fixed.label);
    const auto &planes = parameters.forward.discretization.fixed_planes;
    if (planes.empty())
      return held;
    // A label with a boundary face in a fixed plane is held there.
    for (const auto &cell : mesh->triangulation().active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              const std::array<bool, 3> c =
                fixed_plane_components(planes,
                                       *cell->face(f),
                                       mesh->length_unit());
              if (c[0] || c[1] || c[2])
                held.insert(cell->material_id());
            }
    return Utilities::MPI::compute_set_union(held, comm);
  }

  std::string
  Simulator::unheld_pieces_text() const
  {
    if (!mesh || !forward || contact || forward->loads().has_support())
      return "";
    std::string text;
    for (const UnheldPiece &piece : mesh->unheld_pieces(held_labels()))
      text += (text.empty() ? "" : "; ") +
              piece.text(mm_per_m / parameters.mesh.length_unit);
    return text.empty() ? text :
                          text + " (nothing but its joint holds it against "
                                 "rotation: the tangent is singular there)";
  }
} // namespace RestShape
