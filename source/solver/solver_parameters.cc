// The parameters of subsection Solver: Newton, load stepping, linear solvers.
#include <deal.II/base/utilities.h>

#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/solver/solver_parameters.h>

#include <cmath>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry(
      "Linear solver",
      "auto",
      Patterns::Selection("auto|direct|cg-amg"),
      "auto: direct up to 2500 DoFs with linear elements and 20000 with "
      "quadratic ones (with or without contact), or when some direction is "
      "held by no fixed label; "
      "cg-amg otherwise (the run says which it took), and the direct "
      "solver for the rest of the run where CG fails on a system of up to "
      "150000 DoFs (larger ones: where CG and then GMRES fail). "
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
      "AMG prolongator",
      "plain",
      Patterns::Selection("smoothed|plain"),
      "cg-amg only. plain: the aggregates' rigid-body modes as they are "
      "(unsmoothed aggregation): a third of the AMG's memory and set-up "
      "time of smoothed; twice the CG iterations per Newton step at 1.3 "
      "million DoFs, about as fast up to 164k DoFs, 1.1 times slower at "
      "1.3 million (doc/benchmarks.md, section 2). smoothed: smoothed "
      "aggregation (ML's default: each aggregate's rigid-body modes "
      "smoothed by one damped Jacobi step): the fewest CG iterations, for "
      "when memory is not the limit.");
    prm.declare_entry(
      "Mixed preconditioner",
      "condensed",
      Patterns::Selection("block|condensed"),
      "cg-amg with the mixed formulation only. condensed: AMG on the "
      "condensed tangent (the pressures eliminated), whose volumetric "
      "stiffness K weakens it as K/mu grows. block: CG on the same system, "
      "preconditioned by the block factorisation of the uncondensed one "
      "(displacement and pressure): AMG on the displacement block, which "
      "keeps a bulk modulus of one shear modulus, and a diagonal "
      "approximation of the pressure Schur complement; two AMG cycles per "
      "CG iteration. Measured (doc/benchmarks.md, section 18): on the Lame "
      "shell with P2-P0 block needs 0.30 of the CG iterations and 0.69 of "
      "the time at nu = 0.4999, 0.14 and 0.34 at 0.49999; on the brain "
      "(prm/brain_in_vivo.prm) it is slower at every nu and element (P2-P0 "
      "at 0.4999: 2.4 times the time), and on P1 with the averaged nodal "
      "pressure, which is not inf-sup stable, it needs 4 to 16 times the "
      "iterations; hence the default.");
    prm.declare_entry(
      "Nodal pressure product",
      "split",
      Patterns::Selection("split|assembled"),
      "cg-amg with the mixed formulation of linear tetrahedra (the "
      "averaged nodal pressure) and the condensed preconditioner only: how "
      "CG and the finest level of the AMG multiply by the tangent. split: "
      "the cells' matrix plus one rank-one term per vertex (its volume "
      "stiffness), the default: on the brain (prm/brain_in_vivo.prm) the "
      "mixed forward solve takes 0.80 of the instructions of assembled, "
      "0.75 refined once (doc/benchmarks.md, section 13). assembled: the "
      "assembled matrix, whose rows hold every DoF of the cells around "
      "each vertex (about 3.5 times the cells' matrix's entries), for "
      "comparisons. The same linear systems either way; the direct solver "
      "always factorises the assembled matrix.");
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
      "Direct factorisation",
      "lu",
      Patterns::Selection("lu|ldlt"),
      "The direct solver's factorisation (MUMPS). lu: LU through Trilinos "
      "Amesos, for every matrix. ldlt: on one process and where the tangent "
      "is symmetric (every law and load but a follower pressure on a surface "
      "with free edges), MUMPS's LDL^T of the lower triangle (symmetric "
      "indefinite mode): about half the flops and memory of the LU; the "
      "linear solves of the P2 cantilever at 19,683 DoFs take 0.65 of the "
      "time (doc/model.md). LU elsewhere. The equilibria are the same; with "
      "contact, round-off may change the active-set path.");
    prm.declare_entry(
      "Watchdog steps",
      std::to_string(default_watchdog_steps),
      Patterns::Integer(0, 20),
      "Without contact: a full Newton step at whose end the total potential "
      "energy (in the direct inverse: |R|) lies above the line search's "
      "(Armijo) target is taken anyway, "
      "on trial, and the next steps (with their line searches) have this "
      "many steps to bring the energy below that target; if they do not, "
      "Newton goes back to the state before it and shortens the step as "
      "the line search says (the watchdog of Chamberlain et al. 1982). It "
      "lets through the first full step of large rotations (a beam bending "
      "under its own weight from the straight state, and the direct inverse "
      "of its rest shape), whose shortened steps cost more Newton steps "
      "(doc/benchmarks.md); in the direct inverse a trial that fails fails "
      "its load step. 0: off, every step as the line search says.");
    prm.declare_entry(
      "Check stability",
      "auto",
      Patterns::Selection("auto|true|false"),
      "After the final equilibrium (of the last refinement cycle, and of "
      "an inverse iteration that stops unconverged), compute the smallest "
      "eigenvalues of the constrained tangent against the lumped mass "
      "(1/s^2; shift-invert Lanczos) and the number of negative ones "
      "found, reported in summary.json. An unstable equilibrium (a "
      "negative eigenvalue: a column above its buckling height, a body "
      "free to turn under gravity) stops the run with its mode. auto: "
      "wherever the tangent is symmetric (the check is a question of the "
      "energy), with exact solves by the direct solver or, with cg-amg, a "
      "bounded variant (10 Lanczos steps with CG solves to 1e-3); the run "
      "and summary.json say when and why it was not run. true: the same, "
      "and an input error where the tangent is not symmetric (a follower "
      "pressure on a surface with free edges). false: never.");
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
    split_nodal_tangent       = prm.get("Nodal pressure product") == "split";
    linear_tolerance          = prm.get_double("Linear solver tolerance");
    inexact_newton            = prm.get_bool("Inexact Newton");
    const std::string amg     = prm.get("AMG update");
    amg_update                = amg == "lagged"           ? AmgUpdate::lagged :
                                amg == "reuse aggregates" ? AmgUpdate::reuse_aggregates :
                                                            AmgUpdate::rebuild;
    amg_aggregation_threshold = prm.get_double("AMG aggregation threshold");
    amg_smoothed_aggregation  = prm.get("AMG prolongator") == "smoothed";
    mixed_preconditioner      = prm.get("Mixed preconditioner") == "block" ?
                                  MixedPreconditioner::block :
                                  MixedPreconditioner::condensed;
    tangent_shift             = prm.get_double("Tangent shift");
    max_load_step_halvings    = prm.get_integer("Maximum load step halvings");
    initial_load_steps        = prm.get_integer("Initial load steps");
    watchdog_steps            = prm.get_integer("Watchdog steps");
    symmetric_factorisation   = prm.get("Direct factorisation") == "ldlt";
    const std::string stability = prm.get("Check stability");
    check_stability = stability == "auto" ? StabilityCheck::automatic :
                      stability == "true" ? StabilityCheck::on :
                                            StabilityCheck::off;
    prm.leave_subsection();
    if (!(newton_tolerance > 0))
      throw InputError("",
                       "Solver/Newton tolerance",
                       "expected a positive number");
  }
} // namespace RestShape
