// Newton's residual history: stalled steps and stagnation.
#include <restshape/solver/newton_progress.h>

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
    /// ... and it fell by less than 10 % per step on average;
    constexpr double stagnation_rate = 0.9;
    /// or, at any residual, it stays on a plateau: it fell by less than
    /// 10 % over the whole window (0.99^10 = 0.904)...
    constexpr double no_progress_rate = 0.99;
    /// ... and its largest and smallest value over the window are within
    /// this factor (seen: the P1 brain pushed onto the cutting skull by 2 g
    /// along -y, full and short steps in turn at |R|/|f| = 1.02e-2 to
    /// 1.03e-2, just above near_equilibrium, for 86 steps up to the
    /// iteration cap; while the energy's line search leads Newton far from
    /// an equilibrium, the residual jumps by orders instead).
    constexpr double plateau_band = 1.25;

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

    /// Whether the last stagnation_window accepted steps of @p history
    /// stay within plateau_band of each other.
    bool
    on_plateau(const std::vector<double> &history)
    {
      if (history.size() <= stagnation_window)
        return false;
      const auto [low, high] =
        std::minmax_element(history.end() - 1 - stagnation_window,
                            history.end());
      return *low > 0 && *high <= plateau_band * *low;
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
    const bool   slow      = now < near_equilibrium && rate > stagnation_rate;
    const bool   flat      = rate > no_progress_rate && on_plateau(history);
    if (!((slow || flat) && projected > stagnation_margin * tolerance))
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
