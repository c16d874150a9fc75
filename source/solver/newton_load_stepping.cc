// NewtonSolver: load stepping. Newton from the last equilibrium to the next
// load fraction; a failed increment is halved, an accepted one doubled.

#include <restshape/base/format_text.h>
#include <restshape/solver/newton_solver.h>

#include <cstdio>

namespace RestShape
{
  void
  NewtonSolver::FailedAttempts::add(const double       fraction,
                                    const bool         inverted,
                                    const std::string &text)
  {
    ++count;
    if (!inverted || (inverting > 0 && fraction >= inverting_fraction))
      {
        inverting += inverted;
        return;
      }
    ++inverting;
    inverting_fraction = fraction;
    inverting_text     = text;
  }

  std::string
  NewtonSolver::give_up_text(const SolveStatistics &stats,
                             const FailedAttempts  &failed,
                             const unsigned int     halvings) const
  {
    // Where the load stepping stopped and how compressed its equilibrium
    // is, then what failed beyond it: steps that inverted cells (with one
    // of them), and the last failure.
    std::string text =
      stats.fraction == 0 ?
        format_text("gave up before any load step converged (the first "
                    "increment: %.4g of the full load)",
                    1. / parameters.initial_load_steps) :
        format_text("gave up at %.4f of the full load (", stats.fraction) +
          system.compression_text() + ")";
    text += " after " + std::to_string(halvings - 1) +
            " halvings of the load increment: " + std::to_string(failed.count) +
            " failed attempts";
    if (failed.inverting > 0)
      text +=
        ", " + std::to_string(failed.inverting) +
        format_text(" of them because Newton's steps inverted cells (towards "
                    "%.4g of the load: ",
                    failed.inverting_fraction) +
        failed.inverting_text + ")";
    text += "; the last one: " + stats.failure;
    // Measured on the stability matrix (doc/benchmarks.md, section 4):
    // every P1 case converged with the shift. Not where the last increment
    // failed because its steps invert cells (P2 at gravity x 10: the shift
    // only took longer to fail).
    if (configured_tangent == TangentType::adaptive &&
        parameters.tangent_shift == 0 && failed.inverting == 0)
      text += " (Solver/Tangent shift = 1e-3 may help)";
    return text;
  }

  SolveStatistics
  NewtonSolver::solve_load_steps(
    const std::function<void(double)> &set_fraction)
  {
    SolveStatistics             stats;
    VectorType                  d_converged = system.unknowns();
    LoadSteps                   steps{0, 1. / parameters.initial_load_steps};
    unsigned int                halvings = 0;
    FailedAttempts              failed;
    ActiveSetConstraints::State contact_converged;
    if (contact != nullptr)
      contact_converged = contact->state();

    while (steps.done < 1)
      {
        const double s = steps.next();
        set_fraction(s);
        if (s < 1 || steps.increment < 1)
          pcout << "    Load step to " << format_text("%.4f", s) << std::endl;

        if (solve(stats))
          {
            steps.accept(s);
            d_converged = system.unknowns();
            if (contact != nullptr)
              contact_converged = contact->state();
            ++stats.load_steps;
            continue;
          }
        failed.add(s, stats.cells_inverted, system.inverted_cells_text());
        // Back to the last equilibrium, smaller increment.
        system.unknowns() = d_converged;
        system.unknowns_changed();
        if (contact != nullptr)
          contact->set_state(contact_converged);
        if (++halvings > parameters.max_load_step_halvings)
          {
            set_fraction(steps.done);
            stats.fraction = steps.done;
            stats.failure  = give_up_text(stats, failed, halvings);
            pcout << "    Newton failed: " << stats.failure << std::endl;
            return stats;
          }
        pcout << "    Newton failed (" << stats.failure
              << "); halving the increment" << std::endl;
        steps.reject(s);
      }
    stats.converged = true;
    stats.fraction  = 1;
    stats.failure.clear();
    return stats;
  }
} // namespace RestShape
