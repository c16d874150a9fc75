// Subsection "Solver": Newton, load stepping and the linear solver.
#ifndef restshape_solver_solver_parameters_h
#define restshape_solver_solver_parameters_h

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
    automatic, // direct up to auto_direct_dofs(degree) DoFs, else cg_amg
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

  /// Linear solver = auto: the direct solver up to this many DoFs, by the
  /// element degree (benchmarks/linear_solver_auto, doc/benchmarks.md
  /// section 3). Linear elements: CG + AMG takes 1.0 to 2.1 of the direct
  /// solver's wall time at 567 to 1,443 DoFs, 0.46 to 0.81 from 3,075 on
  /// on the brains and the compact scenes, with contact as without
  /// (forward, inverse and contact solves alike); the slender cantilever
  /// is the exception (1.7). Quadratic elements: 0.52 to 4.2 up to 19,683
  /// DoFs (the cantilever's 4.2 and 3.1), 0.44 to 0.82 from 25,173 on.
  constexpr unsigned int auto_direct_dofs_linear    = 2500;
  constexpr unsigned int auto_direct_dofs_quadratic = 20000;

  /// The limit of Linear solver = auto for elements of @p degree.
  constexpr unsigned int
  auto_direct_dofs(const unsigned int degree)
  {
    return degree > 1 ? auto_direct_dofs_quadratic : auto_direct_dofs_linear;
  }

  enum class MixedPreconditioner
  {
    block,
    condensed
  };

  /// Solver/Watchdog steps (benchmarks/peer, doc/benchmarks.md).
  constexpr unsigned int default_watchdog_steps = 3;

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
    bool amg_smoothed_aggregation = false;
    /// Solver/Mixed preconditioner: with cg-amg and a mixed formulation,
    /// AMG on the displacement block of the uncondensed system inside the
    /// block factorisation (BlockPreconditioner), or on the condensed
    /// tangent (the default).
    MixedPreconditioner mixed_preconditioner = MixedPreconditioner::condensed;
    /// Solver/Nodal pressure product = split: CG + AMG multiply by the
    /// averaged nodal pressure's tangent as SplitTangent does.
    bool           split_nodal_tangent = true;
    double         tangent_shift; // relative; 0: off
    unsigned int   max_load_step_halvings;
    unsigned int   initial_load_steps;
    StabilityCheck check_stability = StabilityCheck::automatic;
    /// Solver/Direct factorisation = ldlt: MUMPS's LDL^T (SymmetricMumps)
    /// for symmetric tangents on one process; false: its LU (Amesos).
    bool symmetric_factorisation = false;
    /// Newton steps a full step taken on trial has to lower the energy
    /// below its Armijo target (NewtonWatchdog; 0: off).
    unsigned int watchdog_steps = default_watchdog_steps;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
