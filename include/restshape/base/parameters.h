// One parameter struct per subsection of the .prm file.
//
// Every struct declares its entries (with defaults and documentation that
// `restshape --print-parameters` shows) and parses them into typed members
// in SI units. Range errors throw InputError naming "Subsection/Parameter".
#ifndef restshape_parameters_h
#define restshape_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/base/label_names.h>
#include <restshape/base/label_values.h>
#include <restshape/base/region.h>

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace RestShape
{
  enum class CellType
  {
    tetrahedra,
    hexahedra
  };

  enum class TangentType
  {
    consistent,
    projected,
    adaptive,
    warped
  };

  /// How the AMG preconditioner follows the tangent (Solver/AMG update).
  enum class AmgUpdate
  {
    rebuild,
    reuse_aggregates,
    lagged
  };

  enum class LinearSolverType
  {
    automatic, // direct up to auto_direct_dofs DoFs, else cg_amg
    direct,
    cg_amg
  };

  /// Solver/Check stability: where the tangent is symmetric (auto), always
  /// (on: an input error where it is not), never (off).
  enum class StabilityCheck
  {
    automatic,
    on,
    off
  };

  /// Linear solver = auto: the direct solver up to this many DoFs.
  constexpr unsigned int auto_direct_dofs = 20000;

  /// Parse a length unit name ("mm" or "m") into metres per unit.
  double
  length_unit_in_metres(const std::string &name, const std::string &parameter);

  /// Parse "x, y, z" (three finite numbers); InputError naming @p parameter.
  dealii::Tensor<1, 3>
  parse_vector(const std::string &text, const std::string &parameter);

  struct MeshParameters
  {
    std::string  file;
    std::string  rest_shape_file;  // optional: the rest shape (same mesh)
    std::string  label_names_file; // optional: "label name" table
    std::string  length_unit_name; // "mm" or "m"
    double       length_unit;      // metres per unit of the file
    CellType     cell_type;
    unsigned int global_refinements;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct DiscretizationParameters
  {
    unsigned int degree;
    TangentType  tangent;
    std::string  tangent_name; // as in the .prm, for summary.json

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct MaterialParameters
  {
    LabelValues youngs_modulus; // Pa
    LabelValues poissons_ratio; // -
    LabelValues density;        // kg/m^3
    /// Materials/Material law as written: a law's name, or 'label:name'
    /// list (parsed against the laws by MaterialTable).
    std::string law = "corotational";
    /// The laws' own parameters (forward/material_laws.h), by name.
    std::map<std::string, LabelValues> law_values;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

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

  struct LoadParameters
  {
    dealii::Tensor<1, 3> gravity;  // m/s^2
    double               pressure; // Pa, positive pushes inward
    bool   follower      = true;   // the pressure acts on the current surface
    double fluid_density = 0;      // kg/m^3 of an immersing fluid
    /// The fluid acts as hydrostatic pressure on the pressure faces (else:
    /// as buoyancy, a reduced density).
    bool             hydrostatic     = false;
    bool             has_fluid_level = false;
    dealii::Point<3> fluid_level;     // m, on the free surface
    std::set<Label>  pressure_labels; // empty: all unfixed labels

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct SolverParameters
  {
    LinearSolverType linear_solver;
    double           newton_tolerance;
    unsigned int     max_newton_iterations;
    double           linear_tolerance;
    bool             inexact_newton;
    AmgUpdate        amg_update;
    /// ML's "aggregation: threshold" (dimensionless, >= 0).
    double amg_aggregation_threshold;
    /// Smoothed aggregation (ML's default prolongator) or plain
    /// (unsmoothed) aggregation: a third of the memory, more CG iterations.
    bool           amg_smoothed_aggregation = false;
    double         tangent_shift; // relative; 0: off
    unsigned int   max_load_step_halvings;
    unsigned int   initial_load_steps;
    StabilityCheck check_stability = StabilityCheck::automatic;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct OutputParameters
  {
    std::string directory;
    bool        write_vtu;
    bool        write_nodal_csv;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct VerificationParameters
  {
    std::string exact_displacement;      // muparser, 3 components; empty: none
    std::string exact_rest_displacement; // the same for X_rest - X

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct RefinementParameters
  {
    enum class Strategy
    {
      global,
      adaptive
    };
    enum class Estimator
    {
      kelly,
      traction_jump
    };
    unsigned int cycles;
    Strategy     strategy;
    Estimator    estimator         = Estimator::kelly;
    double       refine_fraction   = 0.3;  // of the cells, largest indicators
    double       coarsen_fraction  = 0.0;  // of the cells, smallest indicators
    bool         transfer_solution = true; // start from the previous cycle

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct ContactParameters
  {
    std::string     obstacle_file; // empty: no contact
    std::string     length_unit_name;
    double          length_unit;
    bool            inside; // allowed region: inside the closed surface
    std::set<Label> labels; // empty: all
    double          active_set_constant;
    unsigned int    free_updates  = 10;
    unsigned int    plane_changes = 6; // then a crease node's planes are fixed
    double max_outside_fraction   = 0.05; // of the candidates, before solving
    double gap_tolerance          = 0;    // m; 0: round-off
    double pull_tolerance         = 0;    // Pa; 0: round-off

    bool
    enabled() const
    {
      return !obstacle_file.empty();
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct InverseParameters
  {
    enum class Measure
    {
      mean,
      max
    };
    enum class Acceleration
    {
      none,
      anderson
    };
    bool         enabled;
    Measure      measure;
    double       tolerance;     // m, on the error measure
    double       max_tolerance; // m, on the largest nodal error
    unsigned int max_iterations;
    Acceleration acceleration;
    unsigned int anderson_depth;
    /// fixed point: the iteration from the target; direct: first Newton on
    /// the equilibrium at the target with the rest shape as unknown, then
    /// the fixed point from its rest shape (which checks and polishes it).
    enum class Method
    {
      fixed_point,
      direct
    } method = Method::fixed_point;
    /// The share of the reference contact forces the obstacle carries at
    /// the target (0: the least-force rest shape).
    double skull_load_share = 0;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Scenario: what surgery changes after the rest shape (the head turned,
   * the CSF drained, a force field), applied to the pre-stressed model and
   * to the model stress-free in the same geometry (source/app/scenario.cc).
   * Subsection "Scenario", and one "Scenario NAME" per further scenario.
   */
  struct ScenarioParameters
  {
    std::string          name; // empty: subsection "Scenario"
    bool                 enabled = false;
    dealii::Tensor<1, 3> rotation_degrees; // about x, then y, then z
    bool                 has_fluid_level = false;
    dealii::Point<3>     fluid_level; // m (given in the mesh's length unit)
    bool                 has_pressure = false;
    double               pressure     = 0;    // Pa
    dealii::Tensor<1, 3> tissue_acceleration; // m/s^2
    Region               craniotomy;          // m (given in the mesh unit)

    /// The subsection "Scenario" (@p name empty) or "Scenario NAME".
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const std::string        &name = "");
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &name);
    /// "Scenario" or "Scenario NAME": what error messages name.
    std::string
    section() const;
    /// "scenario" or "scenario_NAME": its files and summary keys.
    std::string
    output_name() const;
    /// Read the craniotomy's surface file (Craniotomy = 'surface: FILE',
    /// after Region::scale()): its inside test. Throws InputError naming
    /// the file and Scenario/Craniotomy.
    void
    read_surfaces();
    /// InputError for what an enabled scenario cannot do with these
    /// @p loads, or without the inverse problem (@p inverse_enabled).
    void
    check(const LoadParameters &loads, const bool inverse_enabled) const;
  };

  /// All subsections together: what a scene file describes.
  /// A parameter that names labels.
  struct LabelListEntry
  {
    std::string section, entry;
    /// A list of label:value (a lone value is a value for all labels).
    bool values;
  };

  class LoadTerm;
  struct LoadContext;
  /// Makes a load term of the registry (forward/load_terms.h) that a scene
  /// enables, with its parameters' values, on a discretisation.
  using LoadTermFactory =
    std::function<std::unique_ptr<LoadTerm>(const LoadContext &)>;

  struct Parameters
  {
    MeshParameters           mesh;
    DiscretizationParameters discretization;
    MaterialParameters       materials;
    BoundaryParameters       boundary;
    LoadParameters           loads;
    SolverParameters         solver;
    OutputParameters         output;
    VerificationParameters   verification;
    RefinementParameters     refinement;
    ContactParameters        contact;
    InverseParameters        inverse;
    /// The enabled scenarios: "Scenario", then the named ones as written.
    std::vector<ScenarioParameters> scenarios;
    /// Every parameter that names labels, as written (checked against the
    /// mesh's labels by the Simulator).
    std::vector<LabelList> label_lists;
    /// The registry's load terms the scene enables (parse_load_terms()).
    std::vector<LoadTermFactory> load_terms;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Throws InputError (without file name; the caller adds it).
    /// @p scenario_names: the named scenarios declared (read_scene()).
    /// @p more_label_lists: parameters declared elsewhere that name labels
    /// (load_term_label_entries()).
    void
    parse_parameters(dealii::ParameterHandler          &prm,
                     const std::vector<std::string>    &scenario_names   = {},
                     const std::vector<LabelListEntry> &more_label_lists = {});

    /**
     * Replace the label names in every label list of @p prm by their
     * labels (replace_label_names()), before parse_parameters(). Throws
     * InputError naming the parameter for an unknown name.
     */
    static void
    replace_label_names(
      dealii::ParameterHandler          &prm,
      const LabelNames                  &names,
      const std::vector<LabelListEntry> &more_label_lists = {});
  };
} // namespace RestShape

#endif
