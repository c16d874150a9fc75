// Subsection "Discretization": the element degree and the tangent; and the
// fixed labels of subsection "Boundary conditions".
#ifndef restshape_fem_discretization_parameters_h
#define restshape_fem_discretization_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/label_values.h>
#include <restshape/base/tangent_type.h>

#include <string>
#include <vector>

namespace RestShape
{
  struct DiscretizationParameters
  {
    unsigned int degree;
    TangentType  tangent;
    std::string  tangent_name; // as in the .prm, for summary.json
    /// Boundary conditions/Fixed labels.
    std::vector<FixedLabel> fixed_labels;

    /// Whether every component of @p label is fixed.
    bool
    fully_fixed(const Label label) const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
