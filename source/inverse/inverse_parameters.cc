// The parameters of subsection Inverse problem.
#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/inverse/inverse_parameters.h>

#include <cmath>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  InverseParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Inverse problem");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Compute the rest shape: the stress-free shape whose "
                      "equilibrium under the loads, supports and contact is "
                      "the mesh geometry (the target, e.g. the segmented "
                      "image). The iteration of Sellier 2011 / Morin et al. "
                      "2015: X_rest <- X_rest + (X_target - X_equilibrium).");
    prm.declare_entry("Error measure",
                      "mean",
                      Patterns::Selection("mean|max"),
                      "Error of an iteration over all nodes: the mean (Morin "
                      "et al.) or the max (Sellier) of |X_target - "
                      "X_equilibrium|.");
    prm.declare_entry("Tolerance",
                      "0.01",
                      Patterns::Double(0),
                      "The iteration has converged when the error measure is "
                      "at most this, in mm (and the largest nodal error at "
                      "most Maximum error tolerance).");
    prm.declare_entry("Maximum error tolerance",
                      "",
                      Patterns::Anything(),
                      "Bound on the largest nodal error |X_target - "
                      "X_equilibrium| at convergence, in mm, so that single "
                      "nodes cannot lag behind a small mean. Empty: 10 times "
                      "Tolerance.");
    prm.declare_entry("Maximum iterations",
                      "50",
                      Patterns::Integer(1),
                      "Rest-shape updates before the iteration stops "
                      "unconverged.");
    prm.declare_entry("Acceleration",
                      "anderson",
                      Patterns::Selection("none|anderson"),
                      "none: the paper's update. anderson: Anderson "
                      "acceleration of the same fixed point (safeguarded: a "
                      "step that makes the error worse or would invert a "
                      "cell falls back to the plain update).");
    prm.declare_entry(
      "Method",
      "direct",
      Patterns::Selection("fixed point|direct"),
      "direct (the default): first Newton's method on the equilibrium at "
      "the target geometry with the rest shape as unknown (Jacobian-free: "
      "each Jacobian product is one residual assembly, preconditioned by "
      "the forward tangent; contact is not part of it), then the fixed "
      "point from that rest shape, which checks it with a forward solve "
      "(with contact) and polishes it where needed. Where the image "
      "crosses the obstacle it solves for the image without contact and "
      "the fixed point takes its rest shape to the admissible target (the "
      "rest shape nearest to needing no obstacle force); when its Newton "
      "fails (large rotations) the fixed point starts from the target. "
      "fixed point: only the rest-shape iteration of Sellier and Morin et "
      "al. from the target (with Acceleration).");
    prm.declare_entry(
      "Skull load share",
      "0",
      Patterns::Double(0, 1),
      "Where contact acts at the target the rest shape is not unique: the "
      "obstacle may carry any part of the load there. 0 (the default): the "
      "least-force rest shape, which the direct inverse finds (the fixed "
      "labels carry the load; the obstacle force at the target is next to "
      "zero). s > 0: the rest shape in which the obstacle carries s times "
      "the reference contact forces, node by node: those of the body "
      "stress-free at the (admissible) target settling under the scene's "
      "loads onto the obstacle, with contact only where it touches at the "
      "target (1: the load the fixed labels do not carry when the body is "
      "stress-free there). Needs Method = direct and Contact/Obstacle "
      "file. The fixed point's rest shape, from the target, carries about "
      "what share 1 states (its first forward solve is the reference solve).");
    prm.declare_entry("Anderson depth",
                      "5",
                      Patterns::Integer(1, 20),
                      "Number of previous iterates Anderson acceleration "
                      "uses.");
    prm.leave_subsection();
  }

  void
  InverseParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Inverse problem");
    enabled = prm.get_bool("Enabled");
    method =
      prm.get("Method") == "direct" ? Method::direct : Method::fixed_point;
    measure = prm.get("Error measure") == "max" ? Measure::max : Measure::mean;
    tolerance = prm.get_double("Tolerance") * 1e-3;
    {
      const std::string text =
        dealii::Utilities::trim(prm.get("Maximum error tolerance"));
      constexpr double default_ratio = 10;
      max_tolerance                  = default_ratio * tolerance;
      if (!text.empty())
        {
          char        *end   = nullptr;
          const double value = std::strtod(text.c_str(), &end);
          if (end == text.c_str() || *end != '\0' || !(value > 0))
            throw InputError("",
                             "Inverse problem/Maximum error tolerance",
                             "'" + text +
                               "': expected a positive length in mm, or "
                               "nothing for 10 times Tolerance");
          max_tolerance = value * 1e-3;
        }
    }
    max_iterations   = prm.get_integer("Maximum iterations");
    acceleration     = prm.get("Acceleration") == "none" ? Acceleration::none :
                                                           Acceleration::anderson;
    anderson_depth   = prm.get_integer("Anderson depth");
    skull_load_share = prm.get_double("Skull load share");
    if (skull_load_share > 0 && method != Method::direct)
      throw InputError("",
                       "Inverse problem/Skull load share",
                       "a rest shape that carries a stated skull load is "
                       "found by the direct inverse: expected Method = "
                       "direct, or a share of 0");
    prm.leave_subsection();
    if (enabled && !(tolerance > 0))
      throw InputError("",
                       "Inverse problem/Tolerance",
                       "expected a positive tolerance in mm");
  }

} // namespace RestShape
