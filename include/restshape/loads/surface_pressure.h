// The surface pressure on the pressure faces: a uniform pressure and the
// CSF's hydrostatic pressure (SurfaceLoad), as a follower or a dead load,
// less what an opening of the skull takes off.
#ifndef restshape_loads_surface_pressure_h
#define restshape_loads_surface_pressure_h

#include <restshape/base/region.h>
#include <restshape/loads/environment_parameters.h>
#include <restshape/loads/load_registry.h>
#include <restshape/loads/load_term.h>
#include <restshape/loads/surface_load.h>
#include <restshape/mesh/cavity_walls.h>

#include <memory>

namespace RestShape
{
  /**
   * The pressure on the boundary faces of Loads/Pressure labels. Dead:
   * -p(X) N dA on the faces of the mesh geometry. Follower: -p(x) cof(F) N
   * dA on the current faces, x = X + d, with its tangent and, where it is
   * conservative, its potential. Its loads: SurfaceLoad::pressure_name and
   * the others of SurfaceLoad.
   */
  class SurfacePressure : public LoadTerm
  {
  public:
    /// Loads/Surface pressure, Pressure load, Pressure labels.
    struct Settings
    {
      double          pressure = 0;    // Pa, positive pushes inward
      bool            follower = true; // acts on the current surface
      std::set<Label> labels;          // empty: all unfixed labels
    };

    static LoadTermInfo
    info();

    /// Finds the fluid level (the given one, or the highest point of the
    /// pressure faces against gravity) and whether the tangent is
    /// symmetric. Throws InputError if the fluid wets no pressure face.
    SurfacePressure(const Settings              &settings,
                    const EnvironmentParameters &environment,
                    const LoadContext           &context);

    void
    scene_load(LoadState &load) const override;
    void
    change_load(const ScenarioChange &change, LoadState &load) const override;
    void
    open_load(const ScenarioChange &change, LoadState &load) const override;
    std::string
    change_text(const LoadState &scene,
                const LoadState &changed) const override;
    unsigned int
    open(const Region &opening) override;

    bool
    dead() const override
    {
      return !load->follower();
    }
    void
    assemble_faces(const LoadCell &c) const override;
    dealii::Tensor<1, 3>
    local_resultant(const LoadState  &load,
                    const VectorType &d,
                    const VectorType &w) const override;
    bool
    symmetric() const override
    {
      return is_symmetric;
    }

    /// The pressure, its level and whether it follows the surface.
    const SurfaceLoad &
    surface_load() const
    {
      return *load;
    }
    /// The pressure faces' point (mesh geometry, m) highest against
    /// @p acceleration: the free surface of a fluid that wets them all.
    dealii::Point<3>
    highest_point(const dealii::Tensor<1, 3> &acceleration) const;
    /// Whether any pressure acts under @p load.
    bool
    acts(const LoadState &load) const
    {
      return this->load->acts(SurfaceLoad::field(load, names));
    }
    /// What a term that carries the cavity walls alone claims
    /// (LoadContext::claimed_surfaces).
    static const std::string cavity_walls_name;

  protected:
    /// Which parts of the surface carry it.
    enum class Walls
    {
      outer_and_cavities, // the whole surface
      outer,   // the outer surface (a cavity's own load claims its walls)
      cavities // the walls of the cavities only
    };
    /// The pressure of the loads @p names on the walls @p walls of the
    /// pressure labels (Walls::outer_and_cavities: the outer surface too,
    /// unless a term made before claimed the cavity walls, LoadContext::
    /// claimed_surfaces).
    SurfacePressure(const Settings              &settings,
                    const EnvironmentParameters &environment,
                    const LoadContext           &context,
                    const PressureNames         &names,
                    const Walls                  walls);
    /// The LoadState names of its loads.
    const PressureNames names;

  private:
    /// Whether face @p f of @p cell (at the surface) is on the walls that
    /// carry the pressure.
    bool
    on_walls(const dealii::CellAccessor<3, 3> &cell, const unsigned int f) const
    {
      return cavities == nullptr ||
             cavities->contains(cell, f) == (walls == Walls::cavities);
    }
    /// for_each_boundary_face() over the faces of the labels that carry
    /// the pressure.
    template <typename Function>
    void
    for_each_face(Function &&f, const bool ghosts = false) const
    {
      for_each_boundary_face(
        context.dof_handler,
        context.mesh,
        labels,
        [&](const auto &cell, const unsigned int face) {
          if (on_walls(*cell, face))
            f(cell, face);
        },
        ghosts);
    }
    /// Whether the face @p f of @p cell is in the opening.
    SurfaceLoad::Face
    face_kind(const CellIterator &cell, const unsigned int f) const;
    /// Throws InputError if a hydrostatic fluid's level is above every
    /// pressure face.
    void
    check_level_wets(const dealii::Point<3> &level) const;
    /// Whether the pressure faces form a closed surface or one whose edges
    /// are held (every DoF on them fixed): then a follower pressure is
    /// conservative and its assembled tangent symmetric.
    bool
    closed_or_held() const;
    /// The follower pressure's face terms at quadrature point @p q.
    void
    add_follower(const LoadCell         &c,
                 const PressureField    &field,
                 const unsigned int      q,
                 const SurfaceLoad::Face face) const;

    const Settings              settings;
    const EnvironmentParameters environment;
    const LoadContext           context;
    const Walls                 walls;
    /// The walls of the mesh's cavities, where they matter (null: the
    /// whole surface carries the pressure).
    std::unique_ptr<const CavityWalls> cavities;
    const std::set<Label>              labels;
    std::unique_ptr<SurfaceLoad>       load;
    /// Quadrature points of the pressure faces (mesh geometry, m, owned).
    std::vector<dealii::Point<3>> points;
    Region                        opening; // none by default
    bool                          is_symmetric = true, scene_symmetric = true;
  };
} // namespace RestShape

#endif
