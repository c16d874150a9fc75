// The parameters of subsection Contact.
#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/contact/contact_parameters.h>

#include <cmath>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Obstacle file",
                      "",
                      Patterns::Anything(),
                      "Rigid obstacle: a closed, outward-oriented triangulated "
                      "surface (.stl, .off or .obj), e.g. the inner surface of "
                      "the skull. Empty: no contact.");
    prm.declare_entry("Length unit",
                      "mm",
                      Patterns::Selection("mm|m"),
                      "Unit of the obstacle file's coordinates.");
    prm.declare_entry("Side",
                      "inside",
                      Patterns::Selection("inside|outside"),
                      "inside: nodes must stay inside the closed surface (a "
                      "skull); outside: nodes must stay outside it (an "
                      "obstacle). One-sided, as in Morin et al. 2015: a node "
                      "that is on the wrong side when a solve starts is free "
                      "until it has come back to the allowed side.");
    prm.declare_entry("Contact labels",
                      "",
                      Patterns::Anything(),
                      "Labels whose boundary nodes may touch the obstacle; "
                      "empty: all labels.");
    prm.declare_entry(
      "Gap tolerance",
      "0",
      Patterns::Double(0),
      "How far, in mm, a node may be beyond the obstacle, or an "
      "active node off it, in a converged state (the strict "
      "contact check). 0: the Newton tolerance times the "
      "body's size (round-off).");
    prm.declare_entry(
      "Pull tolerance",
      "0",
      Patterns::Double(0),
      "The largest tensile contact pressure, in Pa, an active node may "
      "carry in a converged state (the strict contact check): the "
      "counterpart of Gap tolerance for the contact force. A node at the "
      "edge of a contact zone on a triangulated obstacle can pull by a "
      "little when held and go through when released; this accepts it "
      "held. 0: the Newton tolerance times the load (round-off).");
    prm.declare_entry("Active set constant",
                      "1",
                      Patterns::Double(0),
                      "c in the complementarity function max(0, p - c g) of "
                      "the primal-dual active set, as a multiple of E_max / h "
                      "(largest Young's modulus over the smallest cell "
                      "diameter), so that c g is a pressure in Pa. It "
                      "decides only when an active node that a step left "
                      "off the obstacle (g > 0) is released: when its "
                      "pressure is below c g. 1: the stress E_max g / h of "
                      "a cell strained by g / h; larger values release nodes "
                      "that slide over the curved obstacle by a fraction of "
                      "the gap tolerance, and the set takes more Newton "
                      "steps to settle (100: 2.9 times as many on the "
                      "brain, doc/contact.md). Every converged state meets "
                      "the same contact conditions whatever the value.");
    prm.declare_entry(
      "Free active-set updates",
      "10",
      Patterns::Integer(1),
      "Active-set updates per solve in which nodes may be "
      "released; afterwards the set only grows (and nodes "
      "that pull on the obstacle are released at the Newton "
      "steps whose residual is below the load, and once Newton "
      "has converged). Lower it (e.g. 4) for large contact zones "
      "on curved obstacles, where the set otherwise wanders "
      "(the brain).");
    prm.declare_entry(
      "Maximum outside fraction",
      "0.05",
      Patterns::Double(0, 1),
      "Largest fraction of the contact candidates (boundary nodes of the "
      "contact labels) that may lie on the wrong side of the obstacle, "
      "deeper than 5 % of the body's size, in the target geometry; more "
      "stops the run before solving (a misplaced obstacle, or one in other "
      "units). Shallower crossings (a segmented skull that cuts into the "
      "brain) are allowed: the inverse problem then aims at the admissible "
      "target, the target projected onto the obstacle.");
    prm.declare_entry(
      "Crease plane changes",
      "6",
      Patterns::Integer(0),
      "A contact node in a crease of the triangulated obstacle holds the "
      "planes of the faces meeting there (doc/contact.md). Once the planes it "
      "holds have changed more than this many times in a solve (2-cycles, "
      "seen at heavy load), they are fixed for the rest of the solve: linear "
      "constraints that Newton meets exactly. Such a node may end slightly "
      "off the surface; summary.json reports how many there are "
      "(fixed_plane_nodes) and how far (fixed_plane_distance_mm). 0 fixes "
      "the planes at their first change.");
    prm.leave_subsection();
  }

  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    obstacle_file    = dealii::Utilities::trim(prm.get("Obstacle file"));
    length_unit_name = prm.get("Length unit");
    length_unit =
      length_unit_in_metres(length_unit_name, "Contact/Length unit");
    inside = prm.get("Side") == "inside";
    labels =
      parse_label_set(prm.get("Contact labels"), "Contact/Contact labels");
    active_set_constant  = prm.get_double("Active set constant");
    free_updates         = prm.get_integer("Free active-set updates");
    plane_changes        = prm.get_integer("Crease plane changes");
    max_outside_fraction = prm.get_double("Maximum outside fraction");
    gap_tolerance        = prm.get_double("Gap tolerance") * 1e-3;
    pull_tolerance       = prm.get_double("Pull tolerance");
    prm.leave_subsection();
    if (!(active_set_constant > 0))
      throw InputError("",
                       "Contact/Active set constant",
                       "expected a positive number");
  }
} // namespace RestShape
