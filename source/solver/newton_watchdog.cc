#include <restshape/solver/newton_watchdog.h>

namespace RestShape
{
  NewtonWatchdog::NewtonWatchdog(const unsigned int steps)
    : steps(steps)
  {}

  bool
  NewtonWatchdog::may_let_through() const
  {
    return steps > 0 && !active && !blocked && trials < max_trials;
  }

  void
  NewtonWatchdog::let_through(const VectorType &start,
                              const double      target_energy)
  {
    kept_state = start;
    target     = target_energy;
    taken      = 0;
    active     = true;
    ++trials;
  }

  NewtonWatchdog::Verdict
  NewtonWatchdog::judge(const double energy)
  {
    // The step after a return to the kept state is the line search's own:
    // once it is accepted, trials are allowed again.
    blocked = false;
    if (!active)
      return Verdict::none;
    if (energy <= target)
      {
        active = false;
        return Verdict::cleared;
      }
    if (++taken < steps)
      return Verdict::none;
    active  = false;
    blocked = true;
    return Verdict::restore;
  }

  bool
  NewtonWatchdog::abandon()
  {
    if (!active)
      return false;
    active  = false;
    blocked = true;
    return true;
  }

  const VectorType &
  NewtonWatchdog::checkpoint() const
  {
    return kept_state;
  }

  unsigned int
  NewtonWatchdog::trial_steps() const
  {
    return taken;
  }
} // namespace RestShape
