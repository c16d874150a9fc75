// The parameters of subsection Boundary conditions.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/forward/boundary_parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  BoundaryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Fixed labels",
                      "",
                      Patterns::Anything(),
                      "Labels whose nodes are fixed (zero displacement): "
                      "'label' fixes all components of every node of the "
                      "cells with that label, 'label:xy' only the listed "
                      "components; a label may be a range. Example: "
                      "'3, 5:xy, 7-9'.");
    prm.declare_entry("Elastic support stiffness",
                      "0",
                      Patterns::Double(),
                      "Stiffness k in N/m^3 (Pa of traction per m of "
                      "displacement) of an elastic foundation on the outer "
                      "faces: traction -k u per unit area of the rest shape's "
                      "faces, u the displacement from the rest shape, in "
                      "every direction. It stands for tethers such "
                      "as the arachnoid trabeculae between brain and skull, "
                      "which are stress-free in the rest shape. 1e4 N/m^3 "
                      "(10 Pa per mm) holds a 1.5 kPa brain against rotating "
                      "freely in a frictionless skull. 0: none.");
    prm.declare_entry("Elastic support labels",
                      "",
                      Patterns::Anything(),
                      "The elastic support acts on the outer faces of cells "
                      "with these labels; empty: all labels that are not "
                      "fully fixed.");
    prm.leave_subsection();
  }

  void
  BoundaryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    fixed_labels      = parse_fixed_labels(prm.get("Fixed labels"),
                                      "Boundary conditions/Fixed labels");
    support_stiffness = prm.get_double("Elastic support stiffness");
    if (!(support_stiffness >= 0))
      throw InputError("",
                       "Boundary conditions/Elastic support stiffness",
                       "'" + prm.get("Elastic support stiffness") +
                         "': expected a stiffness >= 0 in N/m^3");
    support_labels =
      parse_label_set(prm.get("Elastic support labels"),
                      "Boundary conditions/Elastic support labels");
    prm.leave_subsection();
  }
} // namespace RestShape
