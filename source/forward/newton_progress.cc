// Newton's residual history: stalled steps and stagnation.
#include <restshape/forward/newton_progress.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace RestShape
{
  namespace
  {
    /// Accepted steps (since the constraints last changed) whose mean rate
    /// tells whether Newton can still reach the tolerance.
    constexpr unsigned int stagnation_window = 10;
    /// Newton gives up a load step when, at that rate, the steps it has
    /// left would end above this many times the tolerance...
    constexpr double stagnation_margin = 1e4;
    /// ... its relative residual is below this...
    constexpr double near_equilibrium = 1e-2;
    /// ... and it fell by less than 10 % per step on average.
    constexpr double stagnation_rate = 0.9;

    /// The mean factor per step by which the residual fell over the last
    /// stagnation_window accepted steps of @p history (at most 1); 0 while
    /// the history is shorter.
    double
    mean_rate(const std::vector<double> &history)
    {
      if (history.size() <= stagnation_window)
        return 0;
      const double now    = history.back();
      const double before = history[history.size() - 1 - stagnation_window];
      if (!(now > 0 && before > 0))
        return 0;
      return std::min(1., std::pow(now / before, 1. / stagnation_window));
    }
  } // namespace

  bool
  stalled(const std::vector<double> &history, const double now)
  {
    return history.size() >= 2 &&
           std::abs(history.back() - now) <= 1e-6 * now &&
           history.back() > 0.5 * history[history.size() - 2];
  }

  std::string
  stagnation(const std::vector<double> &history,
             const double               now,
             const unsigned int         steps_left,
             const double               tolerance,
             const unsigned int         max_steps)
  {
    const double rate      = mean_rate(history);
    const double projected = now * std::pow(rate, double(steps_left));
    if (!(now < near_equilibrium && rate > stagnation_rate &&
          projected > stagnation_margin * tolerance))
      return "";
    char text[400];
    std::snprintf(text,
                  sizeof(text),
                  "Newton stagnates at |R|/|f| = %.3e: at the mean rate of "
                  "its last %u steps, the %u iterations left would end at "
                  "%.1e, above the tolerance %.1e (Solver/Maximum Newton "
                  "iterations = %u)",
                  now,
                  stagnation_window,
                  steps_left,
                  projected,
                  tolerance,
                  max_steps);
    return text;
  }
} // namespace RestShape
