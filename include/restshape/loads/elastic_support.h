// The elastic support: tethers of stiffness k (Boundary conditions/Elastic
// support stiffness) on the boundary faces of the support labels.
#ifndef restshape_loads_elastic_support_h
#define restshape_loads_elastic_support_h

#include <restshape/loads/load_registry.h>
#include <restshape/loads/load_term.h>

namespace RestShape
{
  /**
   * Traction -k (d - w) per unit area of the rest shape's faces (the
   * tethers belong to the tissue; the same whichever geometry is the
   * mesh), energy k/2 |d - w|^2.
   */
  class ElasticSupport : public LoadTerm
  {
  public:
    /// Boundary conditions/Elastic support stiffness and labels.
    struct Settings
    {
      double stiffness = 0;   // N/m^3: traction (Pa) per m of displacement
      std::set<Label> labels; // empty: all labels not fully fixed
    };

    static LoadTermInfo
    info();

    ElasticSupport(const Settings &settings, const LoadContext &context);

    bool
    dead() const override
    {
      return false;
    }
    /// A support where its stiffness is not zero.
    bool
    is_support() const override
    {
      return k > 0;
    }
    void
    assemble_faces(const LoadCell &c) const override;
    dealii::Tensor<1, 3>
    local_resultant(const LoadState  &load,
                    const VectorType &d,
                    const VectorType &w) const override;

  private:
    const double          k; // N/m^3
    const std::set<Label> labels;
    const LoadContext     context;
  };
} // namespace RestShape

#endif
