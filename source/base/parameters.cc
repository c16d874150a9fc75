#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  namespace
  {
    const std::vector<LabelListEntry> label_list_entries = {
      {"Materials", "Young's modulus", true},
      {"Materials", "Poisson's ratio", true},
      {"Materials", "Density", true},
      {"Materials", "Material law", true},
      {"Boundary conditions", "Fixed labels", false},
      {"Boundary conditions", "Elastic support labels", false},
      {"Loads", "Pressure labels", false},
      {"Contact", "Contact labels", false}};
  } // namespace

  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  dealii::Tensor<1, 3>
  parse_vector(const std::string &text, const std::string &parameter)
  {
    const std::array<double, 3> v = parse_triple(parameter, text);
    return dealii::Tensor<1, 3>({v[0], v[1], v[2]});
  }

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
                      "Mesh file: gmsh (.msh, any version; physical volume "
                      "tags are the labels, $PhysicalNames their names), "
                      "VTK legacy ASCII unstructured grid (.vtk) or VTK XML "
                      "unstructured grid (.vtu; labels from the cell-data "
                      "array label or MaterialID) or "
                      "Abaqus (.inp; C3D4/C3D8 elements, element sets "
                      "numbered 1, 2, ... in order are the labels, their "
                      "names the names). Linear tetrahedra or hexahedra. "
                      "The labels are used by Materials, Boundary "
                      "conditions, Loads and Contact. Relative paths are "
                      "relative to the working directory.");
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
    prm.declare_entry("Label names",
                      "",
                      Patterns::Anything(),
                      "Optional: a table of 'label name' lines (e.g. the "
                      ".nii.txt table of an atlas) that names the labels "
                      "of Mesh/File, in addition to its own gmsh "
                      "$PhysicalNames (which restshape-mesh writes). Every "
                      "label list of the scene (Materials, Boundary "
                      "conditions, Loads, Contact) accepts these names "
                      "where it accepts a label, e.g. 'cerebrum:1500'.");
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
    label_names_file = dealii::Utilities::trim(prm.get("Label names"));
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
    prm.declare_entry(
      "Material law",
      "corotational",
      Patterns::Anything(),
      "The hyperelastic law of the tissue: one name for all labels or a "
      "'label:name' list (ranges and '*' as for Young's modulus). "
      "corotational: linear elasticity in the rotated frame of each point "
      "(stiffness constant, fast; cells can collapse under compressive "
      "strains of order one); neo-Hookean: compressible neo-Hookean, "
      "W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2 (its energy grows "
      "without bound as a cell collapses: for strains of order one); "
      "Ogden: compressible one-term Ogden, W = 2 mu/alpha^2 (sum of the "
      "principal stretches to the power alpha - 3 - alpha ln J) + lambda/2 "
      "(ln J)^2, with alpha from Ogden alpha (the brain's law: Budday et al. "
      "2017). All take mu and lambda from Young's modulus and Poisson's "
      "ratio (mu = E / (2 (1 + nu))), and agree at small strain.");
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
    law     = prm.get("Material law");
    prm.leave_subsection();

    const auto where = [](const LabelValues &values, const Label l) {
      if (l != dealii::numbers::invalid_material_id)
        return " for label " + std::to_string(l);
      return std::string(values.per_label.empty() ? " (all labels)" :
                                                    " (the default '*')");
    };
    // Beyond any material (diamond: 1.2e12 Pa; the softest tissues: 1e2):
    // such values overflow the stiffness matrix or vanish in it.
    constexpr double min_youngs_modulus = 1e-3, max_youngs_modulus = 1e15;
    constexpr double max_density = 1e6; // kg/m^3 (osmium: 22,600)
    for (const auto &[label, E] : youngs_modulus.listed())
      if (!(E >= min_youngs_modulus && E <= max_youngs_modulus))
        throw InputError("",
                         "Materials/Young's modulus",
                         "E = " + number_text(E) + " Pa" +
                           where(youngs_modulus, label) + "; expected " +
                           number_text(min_youngs_modulus) + " Pa <= E <= " +
                           number_text(max_youngs_modulus) + " Pa");
    for (const auto &[label, nu] : poissons_ratio.listed())
      if (!(nu > -1 && nu < 0.5))
        throw InputError("",
                         "Materials/Poisson's ratio",
                         "nu = " + number_text(nu) +
                           where(poissons_ratio, label) +
                           "; expected -1 < nu < 0.5");
    for (const auto &[label, rho] : density.listed())
      if (!(rho >= 0 && rho <= max_density))
        throw InputError("",
                         "Materials/Density",
                         "rho = " + number_text(rho) + " kg/m^3" +
                           where(density, label) + "; expected 0 <= rho <= " +
                           number_text(max_density) + " kg/m^3");
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
    ScenarioParameters::declare_parameters(prm);
  }

  void
  Parameters::parse_parameters(
    ParameterHandler                  &prm,
    const std::vector<std::string>    &scenario_names,
    const std::vector<LabelListEntry> &more_label_lists)
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
    // The fluid levels are given in the mesh's length unit.
    loads.fluid_level *= mesh.length_unit;
    std::vector<std::string> names = {""};
    names.insert(names.end(), scenario_names.begin(), scenario_names.end());
    for (const std::string &name : names)
      {
        ScenarioParameters scenario;
        scenario.parse_parameters(prm, name);
        if (!scenario.enabled)
          continue;
        scenario.fluid_level *= mesh.length_unit;
        scenario.craniotomy.scale(mesh.length_unit);
        scenario.read_surfaces();
        scenario.check(loads, inverse.enabled);
        scenarios.push_back(scenario);
      }
    std::vector<LabelListEntry> entries = label_list_entries;
    entries.insert(entries.end(),
                   more_label_lists.begin(),
                   more_label_lists.end());
    for (const LabelListEntry &e : entries)
      {
        prm.enter_subsection(e.section);
        label_lists.push_back(
          {e.section + "/" + e.entry, prm.get(e.entry), e.values});
        prm.leave_subsection();
      }
    if (inverse.skull_load_share > 0 && contact.obstacle_file.empty())
      throw InputError("",
                       "Inverse problem/Skull load share",
                       "there is no obstacle to carry a load: expected "
                       "Contact/Obstacle file, or a share of 0");
  }

  void
  Parameters::replace_label_names(
    ParameterHandler                  &prm,
    const LabelNames                  &names,
    const std::vector<LabelListEntry> &more_label_lists)
  {
    std::vector<LabelListEntry> entries = label_list_entries;
    entries.insert(entries.end(),
                   more_label_lists.begin(),
                   more_label_lists.end());
    for (const LabelListEntry &e : entries)
      {
        prm.enter_subsection(e.section);
        prm.set(e.entry,
                RestShape::replace_label_names(prm.get(e.entry),
                                               e.section + "/" + e.entry,
                                               names,
                                               e.values));
        prm.leave_subsection();
      }
  }
} // namespace RestShape
