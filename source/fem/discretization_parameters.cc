// The parameters of subsection Discretization, and the fixed labels of
// Boundary conditions (the discretisation's constraints).
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/fem/discretization_parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  DiscretizationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    prm.declare_entry("Polynomial degree",
                      "1",
                      Patterns::Integer(1, 2),
                      "Degree of the Lagrange elements: 1 (P1 tetrahedra or "
                      "Q1 hexahedra) or 2 (P2 / Q2).");
    prm.declare_entry(
      "Tangent",
      "consistent",
      Patterns::Selection("consistent|projected|adaptive|warped"),
      "Newton tangent of the material law (Materials/Material law). "
      "consistent: the exact derivative (for the co-rotational law "
      "including the derivative of the rotation; quadratic convergence). "
      "projected: the exact derivative with its negative eigenvalues (the "
      "rotational modes of compressed points) set to zero, "
      "so the stiffness stays positive semi-definite "
      "(projected Newton; equal to consistent wherever that "
      "is positive; converges linearly where it differs). "
      "adaptive: consistent, but after a Newton step whose "
      "line search had to shorten the step, one step with "
      "the projected tangent. warped: co-rotational law only, R K0 R^T as "
      "in SOFA and Mueller et al. 2002 (no dR term; linear convergence), "
      "kept for comparison; other laws use their exact tangent.");
    prm.declare_entry(
      "Formulation",
      "auto",
      Patterns::Selection("auto|displacement|mixed"),
      "How the element carries the volume change. displacement: the "
      "pointwise J = det F of the displacement element (locks as Poisson's "
      "ratio nears 0.5: on a thick shell under pressure, P1 at nu = 0.4977 "
      "moves 0.29 of the exact displacement). mixed: the law's isochoric "
      "part pointwise and the volumetric energy U(J) = K/2 (ln J)^2 (K the "
      "bulk modulus) of a volume larger than a point, its pressure "
      "condensed: on quadratic tetrahedra and on hexahedra each cell's "
      "mean dilatation, the integral of J over the cell's rest volume (a "
      "pressure constant per cell: P2-P0, Q1-P0, Q2-P0; on Q2 hexahedra "
      "also a linear one, Q2-P1disc: see Cell pressure); on linear "
      "tetrahedra the averaged nodal pressure (Bonet and Burton 1998, as "
      "Joldes, Wittek and Miller use for brain shift): one volume ratio "
      "per vertex over the cells around it, each label's U(J) on its "
      "share of the vertex's rest volume, a cell's pressure the mean of "
      "its vertices' (its stiffness couples the cells around a vertex, "
      "which widens the matrix; see Nodal pressure at the boundary). "
      "auto: mixed where some label's Poisson's "
      "ratio is 0.49 or above, else displacement (with a warning where "
      "displacement is chosen at 0.49 and above).");
    prm.declare_entry(
      "Cell pressure",
      "auto",
      Patterns::Selection("auto|constant|linear"),
      "The pressure of the mixed formulation (Formulation = mixed) on "
      "elements with a pressure per cell. constant: the cell's mean "
      "dilatation (P2-P0, Q1-P0, Q2-P0). linear: on hexahedra of degree 2 "
      "only, a dilatation and a pressure linear on each cell and "
      "discontinuous across cells, condensed (Q2-P1disc, the element of "
      "deal.II's step-44; Simo, Taylor and Pister 1985); its Newton "
      "iteration is less robust at large first steps (step-44's block: 64 "
      "Newton steps against Q2-P0's 23; Hertz's hemisphere at nu = 0.4999 "
      "pressed on the floor: fails where Q2-P0 converges in 7 s). auto: "
      "constant (P2-P1disc is not stable on tetrahedra, nor Q1-P1disc on "
      "hexahedra). Linear tetrahedra use the averaged nodal pressure "
      "instead.");
    prm.declare_entry(
      "Nodal pressure at the boundary",
      "interior",
      Patterns::Selection("own|interior"),
      "The averaged nodal pressure of linear tetrahedra (Formulation = "
      "mixed, degree 1) at the vertices on the domain's boundary. "
      "interior: a cell gives its volume to its interior vertices only "
      "(to all four where none is interior), so boundary vertices carry "
      "no volume ratio of their own; it converges at the same rate "
      "whatever Poisson's ratio (a thick shell under pressure, nu = "
      "0.4999: 4.5 and 3.0 % RMS error on cells of 2 and 1.4 mm, where "
      "P1 at nu = 0.3 has 5.3 and 3.5 %), and the patch test holds. "
      "own: each boundary vertex has its own volume, a quarter of each "
      "cell around it (Bonet and Burton 1998); its patch is a few cells, "
      "which it holds at nearly constant volume, so from Poisson's ratio "
      "0.495 on the element locks and its error stops falling under "
      "refinement (the same shell: 7.0, 7.1 and 7.5 % on cells of 2, 1.6 "
      "and 1.4 mm); kept for comparison.");
    prm.leave_subsection();
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Fixed labels",
                      "",
                      Patterns::Anything(),
                      "Labels whose nodes are fixed (zero displacement): "
                      "'label' fixes all components of every node of the "
                      "cells with that label, 'label:xy' only the listed "
                      "components; a label may be a range. Example: "
                      "'3, 5:xy, 7-9'.");
    prm.declare_entry(
      "Fixed boundary planes",
      "",
      Patterns::Anything(),
      "Displacement components held on the boundary faces that lie in a "
      "coordinate plane: 'AXIS = VALUE' (VALUE in the mesh's length unit) "
      "holds the plane's normal component there (a symmetry plane of a half "
      "or eighth model: the nodes slide in the plane), 'AXIS = VALUE: "
      "COMPONENTS' the listed ones (a face held in place: 'y = 1: xyz'). "
      "Example: 'x = 0, z = 0, y = 1: xz'. Empty: none.");
    prm.leave_subsection();
  }

  bool
  DiscretizationParameters::fully_fixed(const Label label) const
  {
    for (const FixedLabel &f : fixed_labels)
      if (f.label == label && f.components[0] && f.components[1] &&
          f.components[2])
        return true;
    return false;
  }

  void
  DiscretizationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    degree             = prm.get_integer("Polynomial degree");
    tangent_name       = prm.get("Tangent");
    formulation_name   = prm.get("Formulation");
    cell_pressure_name = prm.get("Cell pressure");
    boundary_shares_to_interior =
      prm.get("Nodal pressure at the boundary") == "interior";
    tangent = tangent_name == "warped"    ? TangentType::warped :
              tangent_name == "projected" ? TangentType::projected :
              tangent_name == "adaptive"  ? TangentType::adaptive :
                                            TangentType::consistent;
    prm.leave_subsection();
    prm.enter_subsection("Boundary conditions");
    fixed_labels = parse_fixed_labels(prm.get("Fixed labels"),
                                      "Boundary conditions/Fixed labels");
    fixed_planes =
      parse_fixed_planes(prm.get("Fixed boundary planes"),
                         "Boundary conditions/Fixed boundary planes");
    prm.leave_subsection();
  }

  void
  DiscretizationParameters::resolve_formulation(const double max_nu,
                                                const bool   simplex)
  {
    const bool locking = max_nu >= nearly_incompressible;
    mixed =
      formulation_name == "mixed" || (formulation_name == "auto" && locking);
    nodal_pressure          = mixed && simplex && degree == 1;
    const bool q2_hexahedra = !simplex && degree == 2;
    if (cell_pressure_name == "linear" && !q2_hexahedra)
      throw InputError(
        "",
        "Discretization/Cell pressure",
        "a linear pressure per cell needs hexahedra of degree 2 (Q2-P1disc; "
        "it is not stable on tetrahedra or Q1 hexahedra); expected constant "
        "or auto");
    linear_cell_pressure =
      mixed && q2_hexahedra && cell_pressure_name == "linear";
    formulation_warning.clear();
    if (locking && !mixed)
      formulation_warning =
        "Poisson's ratio " + number_text(max_nu) +
        " (0.49 or above) with the displacement formulation: the elements "
        "lock, the body is too stiff and the rest shape wrong (on a thick "
        "shell under pressure P1 at nu = 0.4977 moves 0.29 of the exact "
        "displacement); use Discretization/Formulation = mixed";
    formulation_note.clear();
    if (nodal_pressure && !boundary_shares_to_interior &&
        max_nu >= nodal_pressure_stalls)
      formulation_note =
        "at Poisson's ratio " + number_text(max_nu) +
        " (0.495 or above) the averaged nodal pressure's error stops "
        "falling under refinement (on a thick shell under pressure: 6.1, 5.9 "
        "and 5.9 % at nu = 0.4977 with cells of 2, 1.6 and 1.4 mm, where P1 "
        "at nu = 0.3 "
        "reaches 3.5 %); for converged figures use Discretization/"
        "Polynomial degree = 2 (P2-P0) or Discretization/Nodal pressure at "
        "the boundary = interior";
  }
} // namespace RestShape
