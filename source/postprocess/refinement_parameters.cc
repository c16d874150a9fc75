// The parameters of subsection Adaptive refinement.
#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/postprocess/refinement_parameters.h>

#include <cmath>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  RefinementParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptive refinement");
    prm.declare_entry("Cycles",
                      "0",
                      Patterns::Integer(0, 10),
                      "Number of refinement cycles after the first solve; "
                      "every cycle refines, solves again and appends a row "
                      "to convergence.csv.");
    prm.declare_entry("Strategy",
                      "global",
                      Patterns::Selection("global|adaptive"),
                      "global: refine every cell. adaptive: refine where the "
                      "estimated error is largest (hexahedra only: deal.II "
                      "9.4 has no hanging nodes on tetrahedra).");
    prm.declare_entry("Refine fraction",
                      "0.3",
                      Patterns::Double(0, 1),
                      "adaptive: the fraction of the cells with the largest "
                      "error indicators that are refined in every cycle.");
    prm.declare_entry("Coarsen fraction",
                      "0",
                      Patterns::Double(0, 1),
                      "adaptive: the fraction of the cells with the smallest "
                      "error indicators that are coarsened (never below the "
                      "initial mesh).");
    prm.declare_entry("Estimator",
                      "kelly",
                      Patterns::Selection("kelly|traction jump"),
                      "Error indicator, computed in every cycle (written per "
                      "cell as estimated_error in the VTU and in total to "
                      "convergence.csv): kelly = jumps of the gradient of the "
                      "displacement from the rest shape across faces; "
                      "traction jump = jumps of the traction of the material "
                      "law across faces, divided by Young's modulus, "
                      "ignoring faces of fixed cells (right at material "
                      "interfaces and rigid supports, where the exact "
                      "gradient jumps).");
    prm.declare_entry("Transfer solution",
                      "true",
                      Patterns::Bool(),
                      "true: every cycle after the first starts from the "
                      "previous cycle's solution interpolated to the refined "
                      "mesh (the displacement as Newton's initial guess at "
                      "the full load, and for an inverse run the rest shape "
                      "as its first iterate); if Newton fails from there, the "
                      "cycle starts again from the unloaded mesh, and a "
                      "direct inverse again from the target. false: every "
                      "cycle starts from the unloaded mesh (and an inverse "
                      "run from the target shape). With the mixed "
                      "formulation near nu = 0.5 false is faster: the "
                      "transferred state's volume error returns multiplied "
                      "by the bulk modulus.");
    prm.leave_subsection();
  }

  void
  RefinementParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptive refinement");
    cycles = prm.get_integer("Cycles");
    strategy =
      prm.get("Strategy") == "adaptive" ? Strategy::adaptive : Strategy::global;
    refine_fraction   = prm.get_double("Refine fraction");
    coarsen_fraction  = prm.get_double("Coarsen fraction");
    estimator         = prm.get("Estimator") == "kelly" ? Estimator::kelly :
                                                          Estimator::traction_jump;
    transfer_solution = prm.get_bool("Transfer solution");
    if (refine_fraction + coarsen_fraction > 1)
      throw InputError("",
                       "Adaptive refinement/Coarsen fraction",
                       "refine fraction + coarsen fraction = " +
                         std::to_string(refine_fraction + coarsen_fraction) +
                         ": expected at most 1");
    prm.leave_subsection();
  }
} // namespace RestShape
