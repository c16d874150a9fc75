// Subsection "Boundary conditions": fixed labels and the elastic support.
#ifndef restshape_forward_boundary_parameters_h
#define restshape_forward_boundary_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/label_values.h>

#include <set>
#include <vector>

namespace RestShape
{
  struct BoundaryParameters
  {
    std::vector<FixedLabel> fixed_labels;
    double support_stiffness = 0; // N/m^3: traction (Pa) per m of displacement
    std::set<Label> support_labels; // empty: all labels not fully fixed

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
