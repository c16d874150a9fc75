// When the rest-shape iteration stops unconverged.
#ifndef restshape_inverse_stopping_rules_h
#define restshape_inverse_stopping_rules_h

#include <string>
#include <vector>

namespace RestShape
{
  /// "1.234 mm": a length in m as text in mm (4 significant digits).
  std::string
  mm_text(const double metres);

  /**
   * When the inverse iteration stops unconverged: divergence, stagnation,
   * and runs of partial updates that gain nothing (their forward solves
   * keep stopping short, typically where a cell would invert). Fed the
   * error of every accepted iterate.
   */
  class StoppingRules
  {
  public:
    StoppingRules(const double initial, const double tolerance)
      : initial(initial)
      , tolerance(tolerance)
      , previous(initial)
      , best(initial)
    {}

    /// The reason to stop after accepted iteration @p iteration with
    /// error @p error, or "" to go on. @p partial: the update was taken
    /// only up to @p fraction of it, the forward solve having stopped
    /// for @p failure.
    std::string
    check(const unsigned int iteration,
          const double       error,
          const bool         partial,
          const double       fraction,
          const std::string &failure);

    /// The error of the last accepted iterate (the initial one before any).
    double
    last() const
    {
      return previous;
    }

  private:
    /// "stalled: ..." after max_partial partial updates without gain.
    std::string
    stalled_text(const unsigned int iteration,
                 const double       error,
                 const std::string &failure) const;

    static constexpr unsigned int max_partial = 3;
    const double                  initial, tolerance;
    double                        previous, best;
    unsigned int                  since_best = 0, increases = 0;
    std::vector<double>           fractions; // partial run without gain
  };
} // namespace RestShape

#endif
