// The per-label material table, and stress measures.
#ifndef restshape_material_material_table_h
#define restshape_material_material_table_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <restshape/base/label_values.h>
#include <restshape/material/corotational_law.h>
#include <restshape/material/material_law.h>
#include <restshape/material/material_parameters.h>

#include <map>
#include <memory>
#include <set>

namespace RestShape
{
  /// Cauchy stress sigma = P F^T / det F.
  dealii::SymmetricTensor<2, 3>
  cauchy_stress(const Tensor2 &F, const Tensor2 &P);

  double
  von_mises(const dealii::SymmetricTensor<2, 3> &sigma);

  /// Law and density of every label of a mesh.
  class MaterialTable
  {
  public:
    /// Throws InputError if a label has no value or an unknown law.
    MaterialTable(const MaterialParameters &prm, const std::set<Label> &labels);

    const MaterialLaw &
    law(const Label label) const;
    double
    density(const Label label) const;
    double
    youngs_modulus(const Label label) const;

    /// Largest Young's modulus over all labels (Pa).
    double
    max_youngs_modulus() const;

  private:
    struct Entry
    {
      std::shared_ptr<const MaterialLaw> law;
      double                             E, rho;
    };
    std::map<Label, Entry> entries;
  };
} // namespace RestShape

#endif
