// The body force: gravity on the buoyed density, a force field on the
// tissue alone, the buoyancy lost above a drained fluid level.
#ifndef restshape_loads_body_force_h
#define restshape_loads_body_force_h

#include <restshape/loads/environment_parameters.h>
#include <restshape/loads/load_registry.h>
#include <restshape/loads/load_term.h>

namespace RestShape
{
  /**
   * The body force of a LoadState per unit volume of the mesh (target)
   * geometry, whatever the rest shape: the mass is rho dV_mesh (times the
   * mesh's mass ratio, LabelledMesh::mass_ratio()). With Loads/Fluid load =
   * buoyancy an immersing fluid buoys it by rho_fluid dV_mesh. Its loads:
   * "Gravity" (columns: an acceleration, m/s^2, on the buoyed density),
   * "Tissue body force" (an acceleration on the full density, never
   * buoyed) and "Drained buoyancy" (an acceleration and a point of the
   * level above which the tissue has lost its buoyancy).
   */
  class BodyForce : public LoadTerm
  {
  public:
    static LoadTermInfo
    info();

    BodyForce(const EnvironmentParameters &environment,
              const LoadContext           &context);

    void
    scene_load(LoadState &load) const override;
    void
    change_load(const ScenarioChange &change, LoadState &load) const override;
    std::string
    change_text(const LoadState &scene,
                const LoadState &changed) const override;

    bool
    has_body_force() const override
    {
      return true;
    }
    /// Whether the fluid drained above a level that may cross a cell acts.
    bool
    body_force_varies(const LoadState &load) const override;
    /// The acceleration on the effective density (the cell's, reduced by
    /// the fluid's with Fluid load = buoyancy, times the mesh's mass
    /// ratio), plus the tissue acceleration on the full density, plus the
    /// buoyancy lost where the fluid is drained.
    dealii::Tensor<1, 3>
    body_force(const dealii::CellAccessor<3, 3> &cell,
               const dealii::Point<3>           &X,
               const LoadState                  &load) const override;

  private:
    const EnvironmentParameters environment;
    const LabelledMesh         &mesh;
    const MaterialTable        &materials;
  };
} // namespace RestShape

#endif
