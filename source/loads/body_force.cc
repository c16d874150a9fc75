#include <restshape/loads/body_force.h>

namespace RestShape
{
  using namespace dealii;

  BodyForce::BodyForce(const LoadContext &context)
    : loads(context.parameters.loads)
    , mesh(context.mesh)
    , materials(context.materials)
  {}

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
    // The label, ratio and density looked up once: this runs for every
    // cell of every assembly.
    const double ratio   = mesh.mass_ratio(cell);
    const double density = materials.density(cell.material_id());
    Tensor<1, 3> f =
      ratio * (density - (loads.hydrostatic ? 0. : loads.fluid_density)) *
      load.acceleration;
    if (load.tissue_acceleration.norm_square() > 0)
      f += ratio * density * load.tissue_acceleration;
    // Above the free surface (against the drained acceleration) the
    // tissue has lost its buoyancy.
    if (body_force_varies(load) &&
        load.drained_acceleration * (X - load.fluid_level) < 0)
      f += ratio * loads.fluid_density * load.drained_acceleration;
    return f;
  }
} // namespace RestShape
