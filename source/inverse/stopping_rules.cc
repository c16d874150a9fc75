// StoppingRules: divergence, stagnation and stalls of the inverse iteration.
#include <restshape/base/units.h>
#include <restshape/inverse/stopping_rules.h>

#include <algorithm>
#include <cstdio>

namespace RestShape
{
  std::string
  mm_text(const double metres)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.4g mm", metres * mm_per_m);
    return buffer;
  }

  std::string
  StoppingRules::check(const unsigned int iteration,
                       const double       error,
                       const bool         partial,
                       const double       fraction,
                       const std::string &failure)
  {
    const std::string at = std::to_string(iteration);
    increases            = (error > previous) ? increases + 1 : 0;
    previous             = error;
    if (error > 2 * initial)
      return "diverged: the error grew from " + mm_text(initial) + " to " +
             mm_text(error) + " in " + at + " iterations";
    if (increases >= 3)
      return "diverged: the error grew in 3 iterations in a row, from "
             "its best " +
             mm_text(std::min(best, error)) + " to " + mm_text(error) +
             " at iteration " + at;
    if (error < 0.99 * best)
      {
        best       = error;
        since_best = 0;
        fractions.clear();
        return "";
      }
    ++since_best;
    if (!partial)
      fractions.clear();
    else
      {
        fractions.push_back(fraction);
        if (fractions.size() >= max_partial)
          return stalled_text(iteration, error, failure);
      }
    if (since_best >= 10)
      return "stagnated: the error has not improved by 1 % in 10 "
             "iterations (best " +
             mm_text(best) + ", tolerance " + mm_text(tolerance) + ")";
    return "";
  }

  std::string
  StoppingRules::stalled_text(const unsigned int iteration,
                              const double       error,
                              const std::string &failure) const
  {
    std::string list;
    for (const double f : fractions)
      {
        char buffer[32];
        std::snprintf(buffer, sizeof(buffer), "%.3g", f);
        list += (list.empty() ? "" : ", ") + std::string(buffer);
      }
    return "stalled: the forward solves of the last " +
           std::to_string(max_partial) +
           " updates reached equilibrium only part of the way (" + list +
           " of each) and the error did not improve on its best " +
           mm_text(best) + " (now " + mm_text(error) + ", iteration " +
           std::to_string(iteration) + "); the last one stopped because " +
           failure;
  }
} // namespace RestShape
