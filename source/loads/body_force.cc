#include <restshape/base/vector_text.h>
#include <restshape/loads/body_force.h>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    const std::string gravity = "Gravity", tissue = "Tissue body force",
                      drained = "Drained buoyancy";
  } // namespace

  LoadTermInfo
  BodyForce::info()
  {
    LoadTermInfo i;
    i.name        = "Body force";
    i.description = "Gravity (Loads/Gravity) on the tissue's density, "
                    "buoyed by an immersing fluid (Loads/Fluid load = "
                    "buoyancy); in a scenario a force field on the tissue "
                    "alone and the buoyancy lost above a drained level. "
                    "Per unit volume of the mesh (target) geometry, on the "
                    "mass of the image whatever the rest shape.";
    i.loads       = {gravity, tissue, drained};
    // Loads/Gravity is declared with the environment it shares with the
    // surface pressure.
    i.declare = [](ParameterHandler &) {};
    i.parse   = [](ParameterHandler &prm, const double length_unit) {
      EnvironmentParameters environment;
      environment.parse_parameters(prm, length_unit);
      return LoadTermFactory([environment](const LoadContext &context) {
        return std::make_unique<BodyForce>(environment, context);
      });
    };
    i.scenario_entries = {
      {tissue,
       "0, 0, 0",
       "A body force per unit mass in m/s^2 ('x, y, z') on the tissue "
       "alone, not buoyed: a force field as in Table 1 of Morin et al. 2015 "
       "('9.81, 0, 0': the tissue's weight, sideways).",
       3}};
    return i;
  }

  BodyForce::BodyForce(const EnvironmentParameters &environment,
                       const LoadContext           &context)
    : environment(environment)
    , mesh(context.mesh)
    , materials(context.materials)
  {}

  void
  BodyForce::scene_load(LoadState &load) const
  {
    load.add(gravity, vector_parameters(environment.gravity));
  }

  void
  BodyForce::change_load(const ScenarioChange &change, LoadState &load) const
  {
    // The head turned: gravity (and the buoyancy) with it.
    LoadState::Columns turned = load.columns(gravity);
    for (LoadColumn &c : turned)
      c.parameters = vector_parameters(change.rotation * column_vector(c));
    load.set(gravity, turned);
    // Drained to a level: the tissue above it loses its buoyancy.
    if (change.has_fluid_level && !environment.hydrostatic)
      {
        std::vector<double> p =
          vector_parameters(change.rotation * environment.gravity);
        for (unsigned int d = 0; d < 3; ++d)
          p.push_back(change.fluid_level[d]);
        load.set(drained, {{p, 1.}});
      }
    const Tensor<1, 3> a = change.vector(tissue);
    if (a.norm_square() > 0)
      load.add(tissue, vector_parameters(a));
  }

  std::string
  BodyForce::change_text(const LoadState &scene, const LoadState &changed) const
  {
    const Tensor<1, 3> a = difference(changed, scene).weighted_vector(tissue);
    if (a.norm_square() == 0)
      return "";
    return "tissue body force " + vector_text(a) + " m/s^2 (not buoyed)";
  }

  bool
  BodyForce::body_force_varies(const LoadState &load) const
  {
    return !environment.hydrostatic && environment.fluid_density > 0 &&
           load.acts(drained);
  }

  Tensor<1, 3>
  BodyForce::body_force(const CellAccessor<3, 3> &cell,
                        const Point<3>           &X,
                        const LoadState          &load) const
  {
    // The label, ratio and density looked up once: this runs for every
    // cell of every assembly.
    const double ratio   = mesh.mass_ratio(cell);
    const double density = materials.density(cell.material_id());
    Tensor<1, 3> f =
      ratio *
      (density - (environment.hydrostatic ? 0. : environment.fluid_density)) *
      load.weighted_vector(gravity);
    if (load.acts(tissue))
      f += ratio * density * load.weighted_vector(tissue);
    // Above the free surface (against the drained acceleration) the
    // tissue has lost its buoyancy.
    if (body_force_varies(load))
      for (const LoadColumn &c : load.columns(drained))
        {
          const Tensor<1, 3> a = column_vector(c);
          if (a * (X - Point<3>(column_vector(c, 3))) < 0)
            f += ratio * environment.fluid_density * (c.weight * a);
        }
    return f;
  }
} // namespace RestShape
