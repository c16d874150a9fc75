// What Newton's residual history says: a stalled step (worth measuring the
// round-off level) and a stagnation (a load step worth giving back).
#ifndef restshape_solver_newton_progress_h
#define restshape_solver_newton_progress_h

#include <string>
#include <vector>

namespace RestShape
{
  /**
   * Whether the last accepted step of Newton (the relative residuals
   * @p history of the accepted steps since the constraints last changed;
   * the last one led to @p now) stalled: it kept more than half of the
   * residual. Only then is the round-off level worth measuring.
   */
  bool
  stalled(const std::vector<double> &history, const double now);

  /**
   * Why Newton stagnates, or "" if it may still converge: at the mean
   * rate of the last 10 accepted steps of @p history, the @p steps_left
   * iterations would end above 1e4 times the tolerance @p tolerance, and
   * either its relative residual @p now is near an equilibrium (below
   * 1e-2) and fell by less than 10 % per step on average, or, at any
   * residual, it stays on a plateau: it fell by less than 10 % over those
   * 10 steps, all of them within a factor 1.25 of each other. (Far from
   * an equilibrium, or while Newton speeds up, a slow stretch may end in
   * Newton's quadratic basin; a plateau does not.) @p max_steps:
   * Solver/Maximum Newton iterations, for the message.
   */
  std::string
  stagnation(const std::vector<double> &history,
             const double               now,
             const unsigned int         steps_left,
             const double               tolerance,
             const unsigned int         max_steps);
} // namespace RestShape

#endif
