// A load term of the registry: a dead traction on a patch of the surface
// (a retractor's spatula, a hand pressing on the tissue).
#ifndef restshape_loads_surface_traction_h
#define restshape_loads_surface_traction_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/parameter_parsing.h>
#include <restshape/base/region.h>
#include <restshape/loads/load_registry.h>
#include <restshape/loads/load_term.h>

namespace RestShape
{
  /**
   * Subsection Surface traction: the traction t (Pa, a force per unit
   * area of the mesh geometry's faces, in the mesh's axes) on the
   * boundary faces of its labels whose centres lie in its region. A dead
   * load: f = t dA, times the weight of its load "Surface traction".
   */
  class SurfaceTraction : public LoadTerm
  {
  public:
    struct Settings
    {
      dealii::Tensor<1, 3> traction; // Pa
      std::set<Label>      labels;   // empty: every label not fully fixed
      Region               region;   // mesh units; none: every face
    };

    static LoadTermInfo
    info();

    /// Throws InputError if no face of the labels lies in the region.
    SurfaceTraction(const Settings &settings, const LoadContext &context);

    void
    scene_load(LoadState &load) const override;
    void
    assemble_faces(const LoadCell &c) const override;
    dealii::Tensor<1, 3>
    local_resultant(const LoadState  &load,
                    const VectorType &d,
                    const VectorType &w) const override;

  private:
    /// Whether the face @p f of @p cell carries the traction.
    bool
    loaded(const CellIterator &cell, const unsigned int f) const;

    const dealii::Tensor<1, 3> traction;
    const std::set<Label>      labels;
    Region                     region; // m
    const LoadContext          context;
    /// The loaded faces' area on this rank (m^2, mesh geometry).
    double area = 0;
  };
} // namespace RestShape

#endif
