#include <restshape/solver/tangent_strategy.h>

namespace RestShape
{
  TangentStrategy::TangentStrategy(const TangentType chosen,
                                   const double      tangent_shift)
    : chosen(chosen)
    , shift_start(chosen == TangentType::adaptive ? tangent_shift : 0.)
    , current(chosen == TangentType::adaptive ? TangentType::consistent :
                                                chosen)
  {}

  TangentType
  TangentStrategy::tangent() const
  {
    return current;
  }

  double
  TangentStrategy::shift() const
  {
    return mu;
  }

  bool
  TangentStrategy::raise()
  {
    mu = mu == 0 ? shift_start : 10 * mu;
    return mu <= max_shift;
  }

  bool
  TangentStrategy::accepted(const bool shortened)
  {
    // Near the solution Newton is exact again.
    constexpr double off_below = 1e-3;
    if (shift_start > 0)
      {
        if (shortened)
          return raise();
        mu = mu < off_below * shift_start ? 0 : 0.1 * mu;
      }
    else if (chosen == TangentType::adaptive)
      current = (current == TangentType::consistent && shortened) ?
                  TangentType::projected :
                  TangentType::consistent;
    return true;
  }

  TangentStrategy::Retry
  TangentStrategy::rejected()
  {
    if (chosen != TangentType::adaptive || current != TangentType::consistent)
      return Retry::none;
    if (shift_start > 0)
      return raise() ? Retry::larger_shift : Retry::shift_exhausted;
    current = TangentType::projected;
    return Retry::projected;
  }
} // namespace RestShape
