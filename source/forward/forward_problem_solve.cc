// ForwardProblem: the solves (load stepping and Newton by its
// NewtonSolver), what NewtonSystem asks of it, and solves with the tangent
// of the current state.

#include <restshape/base/units.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/forward/forward_results.h>

#include <cstdio>
#include <limits>

namespace RestShape
{
  using namespace dealii;

  // ------------------------------------------------------------------
  // NewtonSystem

  std::string
  ForwardProblem::inverted_cells_text() const
  {
    return std::to_string(inverted_cells.count) +
           (inverted_cells.count == 1 ? " cell" : " cells") +
           " inverted (det F <= 0), e.g. " +
           cell_location_text(inverted_cells.label, inverted_cells.center);
  }

  std::string
  ForwardProblem::compression_text() const
  {
    // A volume ratio of 1 (or more) compresses nothing: it says so.
    constexpr double  uncompressed = 0.999;
    const Compression c            = most_compressed_cell(*this);
    char              text[96];
    std::snprintf(text,
                  sizeof(text),
                  c.det_F < uncompressed ?
                    "its equilibrium compresses cells to det F = %.3g, " :
                    "no cell of its equilibrium is compressed: smallest "
                    "det F = %.3g, ",
                  c.det_F);
    return text + c.where;
  }

  bool
  ForwardProblem::assemble_residual()
  {
    return assemble(Assemble::residual);
  }

  bool
  ForwardProblem::assemble_step()
  {
    return assemble(Assemble::residual_and_matrix);
  }

  NewtonSystem::Assembled
  ForwardProblem::assembled() const
  {
    return {residual_raw, residual_condensed, external_condensed, total_energy};
  }

  void
  ForwardProblem::restore(const Assembled &a)
  {
    residual_raw       = a.raw;
    residual_condensed = a.condensed;
    external_condensed = a.external;
    total_energy       = a.energy;
  }

  void
  ForwardProblem::unknowns_restarted()
  {
    pressure_prediction.forget();
    nodal_volumes.forget_linearisation();
  }

  double
  ForwardProblem::resolution() const
  {
    return std::numeric_limits<double>::epsilon() *
           discretization_.mesh().minimum_cell_diameter();
  }

  // ------------------------------------------------------------------
  // Solves

  SolveStatistics
  ForwardProblem::solve(const LoadState &target_load, const VectorType &rest)
  {
    const LoadState  start_load = current_load;
    const VectorType w_start    = w;
    // An opening of the skull may have turned the tangent non-symmetric.
    linear_solver->set_symmetric(load_set.symmetric());
    return newton_solver.solve_load_steps([&](const double s) {
      current_load = between(start_load, target_load, s);
      w            = w_start;
      w.sadd(1 - s, s, rest);
      w_ghost = w;
    });
  }

  SolveStatistics
  ForwardProblem::solve_from(const VectorType *guess,
                             const LoadState  &load,
                             const VectorType &rest)
  {
    SolveStatistics first;
    if (guess != nullptr)
      {
        set_state(*guess, rest, load);
        if (contact != nullptr)
          contact->reset();
        if (newton_solver.solve(first))
          {
            first.converged  = true;
            first.fraction   = 1;
            first.load_steps = 1;
            first.failure.clear();
            return first;
          }
        pcout << "    Newton from the initial guess failed (" << first.failure
              << "); starting again from the unloaded state" << std::endl;
      }
    set_state(discretization_.zero_vector(),
              discretization_.zero_vector(),
              LoadState());
    if (contact != nullptr)
      contact->reset();
    SolveStatistics stats = solve(load, rest);
    stats.newton_iterations += first.newton_iterations;
    stats.linear_iterations += first.linear_iterations;
    stats.active_set_changes += first.active_set_changes;
    return stats;
  }

  // ------------------------------------------------------------------
  // Solves with the tangent of the current state

  void
  ForwardProblem::prepare_consistent_tangent()
  {
    const TangentType chosen = tangent_type;
    tangent_type             = TangentType::consistent;
    const bool valid         = assemble(Assemble::residual_and_matrix);
    tangent_type             = chosen;
    AssertThrow(valid, ExcMessage("an inverted cell in an equilibrium"));
    linear_solver->set_symmetric(load_set.symmetric());
    linear_solver->prepare(tangent);
  }

  void
  ForwardProblem::release_linear_solver()
  {
    linear_solver->release();
  }

  void
  ForwardProblem::solve_with_tangent(VectorType       &x,
                                     const VectorType &b,
                                     const double      tolerance)
  {
    linear_solver->solve_prepared(x, b, tolerance);
  }

  bool
  ForwardProblem::tangent_solves_are_exact() const
  {
    return linear_solver->solves_prepared_exactly();
  }
} // namespace RestShape
