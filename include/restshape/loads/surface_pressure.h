// The surface pressure on the pressure faces: a uniform pressure and the
// CSF's hydrostatic pressure (SurfaceLoad), as a follower or a dead load,
// less what an opening of the skull takes off.
#ifndef restshape_loads_surface_pressure_h
#define restshape_loads_surface_pressure_h

#include <restshape/base/region.h>
#include <restshape/loads/load_term.h>
#include <restshape/loads/surface_load.h>

#include <memory>

namespace RestShape
{
  /**
   * The pressure on the boundary faces of Loads/Pressure labels. Dead:
   * -p(X) N dA on the faces of the mesh geometry. Follower: -p(x) cof(F) N
   * dA on the current faces, x = X + d, with its tangent and, where it is
   * conservative, its potential.
   */
  class SurfacePressure : public LoadTerm
  {
  public:
    /// Finds the fluid level (the given one, or the highest point of the
    /// pressure faces against gravity) and whether the tangent is
    /// symmetric. Throws InputError if the fluid wets no pressure face.
    explicit SurfacePressure(const LoadContext &context);

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
    /// A craniotomy: pressure faces centred in @p opening lose the
    /// opening's pressure; a follower tangent turns non-symmetric. Returns
    /// their number. An empty region closes the opening again.
    unsigned int
    open(const Region &opening);

  private:
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
                 const unsigned int      q,
                 const SurfaceLoad::Face face) const;

    const LoadContext            context;
    const std::set<Label>        labels;
    std::unique_ptr<SurfaceLoad> load;
    /// Quadrature points of the pressure faces (mesh geometry, m, owned).
    std::vector<dealii::Point<3>> points;
    Region                        opening; // none by default
    bool                          is_symmetric = true, scene_symmetric = true;
  };
} // namespace RestShape

#endif
