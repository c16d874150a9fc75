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
  /// element degree and whether there is an obstacle (benchmarks/
  /// linear_solver_auto, doc/benchmarks.md section 3). Linear elements:
  /// CG + AMG takes 0.92 (free) and 0.71 (inverse) of the direct solver's
  /// time at 3.6k DoFs but 3.4 times as long with contact (its inexact
  /// steps change the active set: 179 Newton steps against 27); at 12k
  /// it takes 0.65, 0.80 and 0.45 (contact). The contact series crosses
  /// near 7.5k, the others below 3.6k. Quadratic elements: at 25k DoFs
  /// 0.91 (free), 0.79 (contact), 1.20 (inverse); at 91k 0.51 (free).
  constexpr unsigned int auto_direct_dofs_linear         = 4000;
  constexpr unsigned int auto_direct_dofs_linear_contact = 8000;
  constexpr unsigned int auto_direct_dofs_quadratic      = 50000;

  /// The limit of Linear solver = auto for elements of @p degree, with or
  /// without an obstacle (@p contact).
  constexpr unsigned int
  auto_direct_dofs(const unsigned int degree, const bool contact)
  {
    return degree > 1 ? auto_direct_dofs_quadratic :
           contact    ? auto_direct_dofs_linear_contact :
                        auto_direct_dofs_linear;
  }

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
    bool           amg_smoothed_aggregation = false;
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
