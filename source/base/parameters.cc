#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  namespace
  {
    dealii::Tensor<1, 3>
    parse_vector(const std::string &text, const std::string &parameter)
    {
      const auto items = dealii::Utilities::split_string_list(text, ',');
      dealii::Tensor<1, 3> v;
      bool                 ok = (items.size() == 3);
      for (unsigned int d = 0; ok && d < 3; ++d)
        {
          std::size_t pos = 0;
          try
            {
              v[d] = std::stod(items[d], &pos);
            }
          catch (...)
            {
              ok = false;
            }
          ok = ok && pos == items[d].size() && std::isfinite(v[d]);
        }
      if (!ok)
        throw InputError("",
                         parameter,
                         "'" + text +
                           "' is not a vector; expected three numbers "
                           "'x, y, z'");
      return v;
    }
  } // namespace

  double
  length_unit_in_metres(const std::string &name, const std::string &parameter)
  {
    if (name == "mm")
      return 1e-3;
    if (name == "m")
      return 1.0;
    throw InputError("",
                     parameter,
                     "unknown length unit '" + name + "'; expected mm or m");
  }

  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("File",
                      "meshes/column_tet.msh",
                      Patterns::FileName(),
                      "Gmsh mesh file (.msh, format 2.2 or 4.1, ASCII). "
                      "Physical volume tags become the labels used by "
                      "Materials, Boundary conditions and Loads. Relative "
                      "paths are relative to the working directory.");
    prm.declare_entry("Length unit",
                      "mm",
                      Patterns::Selection("mm|m"),
                      "Unit of the coordinates in the mesh file. Internally "
                      "everything is SI; outputs use this unit for lengths.");
    prm.declare_entry("Rest shape file",
                      "",
                      Patterns::Anything(),
                      "Optional: a gmsh file with the same cells and vertices "
                      "as Mesh/File (e.g. the rest_shape.msh of an inverse "
                      "run) whose vertex positions are the stress-free shape. "
                      "The simulation then starts pre-stressed: the body "
                      "rests in that shape and the loads bring it back to "
                      "Mesh/File's geometry. Empty: Mesh/File is stress-free.");
    prm.declare_entry("Cell type",
                      "tetrahedra",
                      Patterns::Selection("tetrahedra|hexahedra"),
                      "tetrahedra: use the tetrahedra of the file. "
                      "hexahedra: split every tetrahedron into four "
                      "hexahedra (edge midpoints, face centroids, centroid), "
                      "keeping labels; a hexahedral file is used as is.");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 8),
                      "Number of uniform refinements of the mesh (each "
                      "splits every cell into 8).");
    prm.leave_subsection();
  }

  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    file = prm.get("File");
    if (file.empty())
      throw InputError("", "Mesh/File", "no mesh file given");
    rest_shape_file  = dealii::Utilities::trim(prm.get("Rest shape file"));
    length_unit_name = prm.get("Length unit");
    length_unit = length_unit_in_metres(length_unit_name, "Mesh/Length unit");
    cell_type   = prm.get("Cell type") == "hexahedra" ? CellType::hexahedra :
                                                        CellType::tetrahedra;
    global_refinements = prm.get_integer("Global refinements");
    prm.leave_subsection();
  }

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
      "Newton tangent of the co-rotational law. consistent: "
      "exact derivative including the derivative of the "
      "rotation (quadratic convergence). projected: the "
      "exact derivative with its negative eigenvalues (the "
      "rotational modes of compressed points) set to zero, "
      "so the stiffness stays positive semi-definite "
      "(projected Newton; equal to consistent wherever that "
      "is positive; converges linearly where it differs). "
      "adaptive: consistent, but after a Newton step whose "
      "line search had to shorten the step, one step with "
      "the projected tangent. warped: R K0 R^T as in SOFA and Mueller "
      "et al. 2002 (no dR term; linear convergence), kept "
      "for comparison.");
    prm.leave_subsection();
  }

  void
  DiscretizationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    degree       = prm.get_integer("Polynomial degree");
    tangent_name = prm.get("Tangent");
    tangent      = tangent_name == "warped"    ? TangentType::warped :
                   tangent_name == "projected" ? TangentType::projected :
                   tangent_name == "adaptive"  ? TangentType::adaptive :
                                                 TangentType::consistent;
    prm.leave_subsection();
  }

  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    prm.declare_entry("Young's modulus",
                      "1500",
                      Patterns::Anything(),
                      "Young's modulus in Pa: one value for all labels, or "
                      "'label:value, label:value' with every label of the "
                      "mesh given a value; a label may be a range "
                      "('1-90:1500') and '*:value' gives every label not "
                      "listed. Must be > 0.");
    prm.declare_entry("Poisson's ratio",
                      "0.45",
                      Patterns::Anything(),
                      "Poisson's ratio, in (-1, 0.5): one value or "
                      "'label:value' list (ranges and '*' as for Young's "
                      "modulus).");
    prm.declare_entry("Density",
                      "1040",
                      Patterns::Anything(),
                      "Density in kg/m^3 of the tissue as imaged (the mass "
                      "of every cell is taken from the mesh geometry and "
                      "kept when the rest shape changes): one value or "
                      "'label:value' list (ranges and '*' as for Young's "
                      "modulus). Must be >= 0.");
    prm.leave_subsection();
  }

  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    youngs_modulus = LabelValues::parse(prm.get("Young's modulus"),
                                        "Materials/Young's modulus");
    poissons_ratio = LabelValues::parse(prm.get("Poisson's ratio"),
                                        "Materials/Poisson's ratio");
    density = LabelValues::parse(prm.get("Density"), "Materials/Density");
    prm.leave_subsection();

    const auto where = [](const LabelValues &values, const Label l) {
      if (l != dealii::numbers::invalid_material_id)
        return " for label " + std::to_string(l);
      return std::string(values.per_label.empty() ? " (all labels)" :
                                                    " (the default '*')");
    };
    for (const auto &[label, E] : youngs_modulus.listed())
      if (!(E > 0))
        throw InputError("",
                         "Materials/Young's modulus",
                         "E = " + number_text(E) + " Pa" +
                           where(youngs_modulus, label) + "; expected E > 0");
    for (const auto &[label, nu] : poissons_ratio.listed())
      if (!(nu > -1 && nu < 0.5))
        throw InputError("",
                         "Materials/Poisson's ratio",
                         "nu = " + number_text(nu) +
                           where(poissons_ratio, label) +
                           "; expected -1 < nu < 0.5");
    for (const auto &[label, rho] : density.listed())
      if (!(rho >= 0))
        throw InputError("",
                         "Materials/Density",
                         "rho = " + number_text(rho) + " kg/m^3" +
                           where(density, label) + "; expected rho >= 0");
  }

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

  void
  LoadParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    prm.declare_entry("Gravity",
                      "0, 0, -9.81",
                      Patterns::Anything(),
                      "Gravitational acceleration in m/s^2, 'x, y, z' in the "
                      "mesh's coordinate frame.");
    prm.declare_entry("Fluid density",
                      "0",
                      Patterns::Double(),
                      "Density in kg/m^3 of a fluid the body is immersed in "
                      "(CSF: about 1007); how it acts is set by Fluid load. "
                      "0: no fluid.");
    prm.declare_entry(
      "Fluid load",
      "buoyancy",
      Patterns::Selection("buoyancy|hydrostatic pressure"),
      "How the fluid of Fluid density acts. buoyancy: every body force acts "
      "on the density minus the fluid's (Archimedes' resultant, as if the "
      "whole body were immersed; a brain of 1040 kg/m^3 in CSF weighs 3.2 % "
      "of its weight). hydrostatic pressure: the full density, and on the "
      "pressure faces below the Fluid level the pressure "
      "rho_fluid a . (x - x_level) in Pa (a: the body acceleration, x the "
      "current position), added to Surface pressure; what CSF does on a "
      "surface whose other parts are held (a closed immersed surface "
      "receives exactly its buoyancy).");
    prm.declare_entry("Fluid level",
                      "",
                      Patterns::Anything(),
                      "A point 'x, y, z' (mesh length unit) on the fluid's "
                      "free surface, which is normal to the body "
                      "acceleration; faces above it are drained. Empty: the "
                      "highest point of the pressure faces (the whole "
                      "surface is wetted). Only with Fluid load = "
                      "hydrostatic pressure.");
    prm.declare_entry("Surface pressure",
                      "0",
                      Patterns::Double(),
                      "Uniform pressure in Pa on the outer surface (e.g. "
                      "CSF), along the inward normal of the faces; see "
                      "Pressure load.");
    prm.declare_entry(
      "Pressure load",
      "follower",
      Patterns::Selection("follower|dead"),
      "follower: the pressure acts on the current (deformed) surface along "
      "its current normal, in every solve (a fluid's pressure; Newton uses "
      "its exact tangent). dead: the same tractions fixed on the faces of "
      "Mesh/File, whatever the body does (right only where the equilibrium "
      "is the mesh geometry itself).");
    prm.declare_entry("Pressure labels",
                      "",
                      Patterns::Anything(),
                      "The pressure acts on the outer faces of cells with "
                      "these labels; empty: all labels that are not fully "
                      "fixed.");
    prm.leave_subsection();
  }

  void
  LoadParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    gravity       = parse_vector(prm.get("Gravity"), "Loads/Gravity");
    pressure      = prm.get_double("Surface pressure");
    follower      = prm.get("Pressure load") == "follower";
    fluid_density = prm.get_double("Fluid density");
    if (!(fluid_density >= 0))
      throw InputError("",
                       "Loads/Fluid density",
                       "'" + prm.get("Fluid density") +
                         "': expected a density >= 0 in kg/m^3");
    hydrostatic = prm.get("Fluid load") == "hydrostatic pressure";
    if (hydrostatic && fluid_density == 0)
      throw InputError("",
                       "Loads/Fluid load",
                       "hydrostatic pressure needs the fluid's density: "
                       "expected Loads/Fluid density > 0 in kg/m^3");
    has_fluid_level = !dealii::Utilities::trim(prm.get("Fluid level")).empty();
    if (has_fluid_level)
      {
        if (!hydrostatic)
          throw InputError("",
                           "Loads/Fluid level",
                           "a fluid level needs Fluid load = hydrostatic "
                           "pressure");
        fluid_level = dealii::Point<3>(
          parse_vector(prm.get("Fluid level"), "Loads/Fluid level"));
      }
    pressure_labels =
      parse_label_set(prm.get("Pressure labels"), "Loads/Pressure labels");
    prm.leave_subsection();
  }

  void
  SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry(
      "Linear solver",
      "auto",
      Patterns::Selection("auto|direct|cg-amg"),
      "auto: direct up to 20000 DoFs or when some direction is held by no fixed label, cg-amg otherwise (the run "
      "says which it took). "
      "direct: sparse LU (MUMPS through Trilinos Amesos). "
      "cg-amg: conjugate gradients preconditioned by "
      "Trilinos ML algebraic multigrid built with the six "
      "rigid-body modes (GMRES if CG breaks down).");
    prm.declare_entry("Newton tolerance",
                      "1e-10",
                      Patterns::Double(0),
                      "Newton stops when the residual norm (N) is below this "
                      "fraction of the norm of the external load vector.");
    prm.declare_entry("Maximum Newton iterations",
                      "50",
                      Patterns::Integer(1),
                      "Newton iterations per load step before the step is "
                      "halved.");
    prm.declare_entry("Linear solver tolerance",
                      "1e-8",
                      Patterns::Double(0, 1),
                      "Relative residual reduction of the iterative linear "
                      "solver (cg-amg) in every Newton step.");
    prm.declare_entry("Inexact Newton",
                      "true",
                      Patterns::Bool(),
                      "cg-amg only. true: the linear tolerance of each Newton "
                      "step follows the residual's progress (Eisenstat and "
                      "Walker's choice 2: 0.1 at the first step, then "
                      "0.9 (|R_k|/|R_k-1|)^2, at most 0.1), but never looser "
                      "than what the Newton tolerance needs nor tighter than "
                      "Linear solver tolerance. false: Linear solver "
                      "tolerance in every step (the same solution, in more "
                      "CG iterations; doc/benchmarks.md).");
    prm.declare_entry(
      "AMG update",
      "lagged",
      Patterns::Selection("rebuild|reuse aggregates|lagged"),
      "cg-amg only. How the AMG preconditioner follows the tangent from one "
      "linear solve to the next on the same mesh. rebuild: a new AMG for "
      "every Newton step. reuse aggregates: the aggregates (coarsening "
      "pattern) of the first build are kept, the prolongators, coarse "
      "matrices and smoothers recomputed (ML's ReComputePreconditioner). "
      "lagged: the AMG of an earlier step is used as it is until CG needs "
      "more than 1.5 times the iterations per decade of residual reduction "
      "that it needed right after the build (or fails), then rebuilt "
      "(the fastest of the three on the brain, doc/benchmarks.md).");
    prm.declare_entry(
      "AMG aggregation threshold",
      "0",
      Patterns::Double(0, 1),
      "cg-amg only. ML's aggregation threshold: when the AMG groups nodes "
      "into aggregates, couplings weaker than this (relative to the "
      "diagonal) are dropped. 0 keeps every coupling, which needs fewer "
      "CG iterations than deal.II's tutorials' 0.02 on the brain, more so "
      "the finer the mesh (doc/benchmarks.md, section 2).");
    prm.declare_entry(
      "Tangent shift",
      "0",
      Patterns::Double(0, 1),
      "Discretization/Tangent = adaptive only. 0: after a Newton step whose "
      "line search had to shorten the step, one step with the projected "
      "tangent. s > 0: instead, the consistent tangent with its diagonal "
      "scaled by (1 + mu) (Levenberg-Marquardt): mu = s after the first "
      "shortened step, 10 mu after each further one, mu / 10 after each "
      "full step (0 below s / 1000); a Newton solve that would need "
      "mu > 1e4 fails (its load increment is halved). Try 1e-3 when "
      "Newton stalls on a large mesh with contact (doc/benchmarks.md).");
    prm.declare_entry("Maximum load step halvings",
                      "10",
                      Patterns::Integer(0, 30),
                      "When Newton fails, the load (or rest-shape change) "
                      "increment is halved at most this many times before "
                      "the solve is declared failed.");
    prm.declare_entry("Initial load steps",
                      "1",
                      Patterns::Integer(1, 1024),
                      "Every solve starts with an increment of 1/N of the "
                      "load (or rest-shape change); after each converged "
                      "increment the next one doubles, up to the whole. "
                      "Raise it for very fine meshes whose first Newton "
                      "steps at the full load invert cells.");
    prm.declare_entry(
      "Check stability",
      "false",
      Patterns::Bool(),
      "After the final equilibrium of every refinement cycle (and of an "
      "inverse iteration that stops unconverged), compute the smallest "
      "eigenvalues of the constrained tangent against the lumped mass "
      "(1/s^2; shift-invert Lanczos) and the number of negative ones "
      "found, reported in summary.json. An "
      "unstable equilibrium (a negative eigenvalue: a column above its "
      "buckling height, a body free to turn under gravity) stops the run "
      "with its mode. Needs Linear solver = direct and a symmetric "
      "tangent.");
    prm.leave_subsection();
  }

  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    const std::string solver  = prm.get("Linear solver");
    linear_solver             = solver == "cg-amg" ? LinearSolverType::cg_amg :
                                solver == "direct" ? LinearSolverType::direct :
                                                     LinearSolverType::automatic;
    newton_tolerance          = prm.get_double("Newton tolerance");
    max_newton_iterations     = prm.get_integer("Maximum Newton iterations");
    linear_tolerance          = prm.get_double("Linear solver tolerance");
    inexact_newton            = prm.get_bool("Inexact Newton");
    const std::string amg     = prm.get("AMG update");
    amg_update                = amg == "lagged"           ? AmgUpdate::lagged :
                                amg == "reuse aggregates" ? AmgUpdate::reuse_aggregates :
                                                            AmgUpdate::rebuild;
    amg_aggregation_threshold = prm.get_double("AMG aggregation threshold");
    tangent_shift             = prm.get_double("Tangent shift");
    max_load_step_halvings    = prm.get_integer("Maximum load step halvings");
    initial_load_steps        = prm.get_integer("Initial load steps");
    check_stability           = prm.get_bool("Check stability");
    if (check_stability && linear_solver == LinearSolverType::cg_amg)
      throw InputError("",
                       "Solver/Check stability",
                       "the stability check needs a direct factorisation "
                       "(shift-invert); expected Solver/Linear solver = "
                       "direct or auto");
    prm.leave_subsection();
    if (!(newton_tolerance > 0))
      throw InputError("",
                       "Solver/Newton tolerance",
                       "expected a positive number");
  }

  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Directory for all results (created if missing). "
                      "Files are written under a temporary name and renamed, "
                      "so an interrupted run never leaves half a file.");
    prm.declare_entry("Write VTU",
                      "true",
                      Patterns::Bool(),
                      "Write the VTU/PVTU fields and the .pvd/.visit "
                      "records. Turn off for benchmarks; summary.json and "
                      "the .csv files are always written.");
    prm.declare_entry("Write nodal CSV",
                      "false",
                      Patterns::Bool(),
                      "Also write nodes.csv: one row per node (every support "
                      "point of the element) with its mesh position (mesh "
                      "length unit), its displacement from the rest shape "
                      "and the shift from the mesh to the rest shape (both "
                      "in mm), for post-processing and for comparing meshes "
                      "node by node (benchmarks/time_vs_error/brain.sh).");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory       = prm.get("Directory");
    write_vtu       = prm.get_bool("Write VTU");
    write_nodal_csv = prm.get_bool("Write nodal CSV");
    prm.leave_subsection();
    if (directory.empty())
      throw InputError("", "Output/Directory", "no directory given");
  }

  void
  VerificationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    prm.declare_entry("Exact displacement",
                      "",
                      Patterns::Anything(),
                      "Optional exact displacement for verification: three "
                      "muparser expressions 'ux; uy; uz' in the mesh's "
                      "length unit, functions of the reference coordinates "
                      "x, y, z (same unit). When given, the L2 and H1 errors "
                      "are computed and written to convergence.csv.");
    prm.declare_entry("Exact rest displacement",
                      "",
                      Patterns::Anything(),
                      "Optional, for the inverse problem: the exact X_rest - "
                      "X_target as three muparser expressions of x, y, z "
                      "(mesh length unit). When given, the errors of the "
                      "computed rest shape are written to convergence.csv.");
    prm.leave_subsection();
  }

  void
  VerificationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    exact_displacement = dealii::Utilities::trim(prm.get("Exact displacement"));
    exact_rest_displacement =
      dealii::Utilities::trim(prm.get("Exact rest displacement"));
    prm.leave_subsection();
  }

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
                      "cycle starts again from the unloaded mesh. false: every "
                      "cycle starts from the unloaded mesh (and an inverse "
                      "run from the target shape).");
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
                      "100",
                      Patterns::Double(0),
                      "c in the complementarity function max(0, p - c g) of "
                      "the primal-dual active set, as a multiple of E_max / h "
                      "(largest Young's modulus over the smallest cell "
                      "diameter), so that c g is a pressure in Pa.");
    prm.declare_entry("Free active-set updates",
                      "10",
                      Patterns::Integer(1),
                      "Active-set updates per solve in which nodes may be "
                      "released; afterwards the set only grows (and nodes "
                      "that pull on the obstacle are released once Newton has "
                      "converged). Lower it (e.g. 4) for large contact zones "
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
    max_iterations = prm.get_integer("Maximum iterations");
    acceleration   = prm.get("Acceleration") == "none" ? Acceleration::none :
                                                         Acceleration::anderson;
    anderson_depth = prm.get_integer("Anderson depth");
    prm.leave_subsection();
    if (enabled && !(tolerance > 0))
      throw InputError("",
                       "Inverse problem/Tolerance",
                       "expected a positive tolerance in mm");
  }

  void
  PrestressComparisonParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Prestress comparison");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "After the inverse problem, apply the same extra body "
                      "force to (1) the pre-stressed model (its equilibrium "
                      "under the scene's loads) and (2) the model that "
                      "starts stress-free from the mesh geometry (no other "
                      "load), as in Table 1 of Morin et al. 2015; write mean "
                      "and max displacement of each to "
                      "prestress_comparison.csv.");
    prm.declare_entry("Extra body force",
                      "0, 9.81, 0",
                      Patterns::Anything(),
                      "The extra acceleration field in m/s^2 ('x, y, z'), "
                      "added to gravity for model (1).");
    prm.leave_subsection();
  }

  void
  PrestressComparisonParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Prestress comparison");
    enabled            = prm.get_bool("Enabled");
    extra_acceleration = parse_vector(prm.get("Extra body force"),
                                      "Prestress comparison/Extra body force");
    prm.leave_subsection();
  }

  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    MeshParameters::declare_parameters(prm);
    DiscretizationParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    BoundaryParameters::declare_parameters(prm);
    LoadParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    VerificationParameters::declare_parameters(prm);
    RefinementParameters::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    InverseParameters::declare_parameters(prm);
    PrestressComparisonParameters::declare_parameters(prm);
  }

  void
  Parameters::parse_parameters(ParameterHandler &prm)
  {
    mesh.parse_parameters(prm);
    discretization.parse_parameters(prm);
    materials.parse_parameters(prm);
    boundary.parse_parameters(prm);
    loads.parse_parameters(prm);
    solver.parse_parameters(prm);
    output.parse_parameters(prm);
    verification.parse_parameters(prm);
    refinement.parse_parameters(prm);
    contact.parse_parameters(prm);
    inverse.parse_parameters(prm);
    prestress_comparison.parse_parameters(prm);
    // The fluid level is given in the mesh's length unit.
    loads.fluid_level *= mesh.length_unit;
    const auto list = [&](const std::string &section,
                          const std::string &entry,
                          const bool         values) {
      prm.enter_subsection(section);
      label_lists.push_back({section + "/" + entry, prm.get(entry), values});
      prm.leave_subsection();
    };
    for (const std::string entry :
         {"Young's modulus", "Poisson's ratio", "Density"})
      list("Materials", entry, true);
    list("Boundary conditions", "Fixed labels", false);
    list("Boundary conditions", "Elastic support labels", false);
    list("Loads", "Pressure labels", false);
    list("Contact", "Contact labels", false);
    if (prestress_comparison.enabled && !inverse.enabled)
      throw InputError("",
                       "Prestress comparison/Enabled",
                       "the comparison needs the pre-stressed model: set "
                       "Inverse problem/Enabled = true");
  }
} // namespace RestShape
