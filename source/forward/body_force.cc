#include <restshape/forward/body_force.h>

namespace RestShape
{
  using namespace dealii;

  BodyForce::BodyForce(const LoadContext &context)
    : loads(context.parameters.loads)
    , mesh(context.mesh)
    , materials(context.materials)
  {}

  double
  BodyForce::effective_density(const CellAccessor<3, 3> &cell) const
  {
    const Label label = cell.material_id();
    return mesh.mass_ratio(cell) *
           (materials.density(label) -
            (loads.hydrostatic ? 0. : loads.fluid_density));
  }

  bool
  BodyForce::body_force_varies(const LoadState &load) const
  {
    return !loads.hydrostatic && loads.fluid_density > 0 &&
           load.drained_acceleration.norm_square() > 0;
  }

  Tensor<1, 3>
  BodyForce::body_force(const CellAccessor<3, 3> &cell,
                        const Point<3>           &X,
                        const LoadState          &load) const
  {
    Tensor<1, 3> f = effective_density(cell) * load.acceleration;
    const double tissue =
      mesh.mass_ratio(cell) * materials.density(cell.material_id());
    if (load.tissue_acceleration.norm_square() > 0)
      f += tissue * load.tissue_acceleration;
    // Above the free surface (against the drained acceleration) the
    // tissue has lost its buoyancy.
    if (body_force_varies(load) &&
        load.drained_acceleration * (X - load.fluid_level) < 0)
      f +=
        mesh.mass_ratio(cell) * loads.fluid_density * load.drained_acceleration;
    return f;
  }
} // namespace RestShape
