// A load term of the registry: the pressure of the CSF in the ventricles
// (every cavity of the mesh) apart from the pressure outside.
#ifndef restshape_loads_ventricular_pressure_h
#define restshape_loads_ventricular_pressure_h

#include <restshape/loads/surface_pressure.h>

namespace RestShape
{
  /**
   * Loads/Ventricular pressure: a uniform pressure (Pa) on the walls of
   * the mesh's cavities (the surface components that enclose no tissue,
   * CavityWalls), a follower or a dead load as Loads/Pressure load says.
   * It claims the cavity walls: the surface pressure (and the CSF's
   * hydrostatic pressure) then acts on the outer surface alone. Not
   * made where the parameter is empty: the cavities then carry the
   * surface pressure as the outer surface does. No opening reaches it.
   */
  class VentricularPressure : public SurfacePressure
  {
  public:
    /// Its load (and parameter) name, "Ventricular pressure".
    static const std::string load_name;

    static LoadTermInfo
    info();

    /// Throws InputError if the mesh has no cavity.
    VentricularPressure(const Settings &settings, const LoadContext &context);

    void
    open_load(const ScenarioChange &, LoadState &) const override
    {}
    unsigned int
    open(const Region &) override
    {
      return 0;
    }
  };
} // namespace RestShape

#endif
