// The elastic support: tethers of stiffness k (Boundary conditions/Elastic
// support stiffness) on the boundary faces of the support labels.
#ifndef restshape_loads_elastic_support_h
#define restshape_loads_elastic_support_h

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
    explicit ElasticSupport(const LoadContext &context);

    bool
    dead() const override
    {
      return false;
    }
    bool
    is_support() const override
    {
      return true;
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
