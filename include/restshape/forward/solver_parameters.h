// Subsection "Solver": Newton, load stepping and the linear solver.
#ifndef restshape_forward_solver_parameters_h
#define restshape_forward_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace RestShape
{
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
} // namespace RestShape

#endif
