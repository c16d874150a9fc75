// The contact conditions of a state, as checked against the obstacle.
#ifndef restshape_solver_active_set_conditions_h
#define restshape_solver_active_set_conditions_h

#include <deal.II/base/point.h>

#include <string>

namespace RestShape
{
  /**
   * The contact conditions at a state, checked against the obstacle's
   * surface itself (not the planes the active set holds): every eligible
   * node on the allowed side (penetration <= the gap tolerance), every
   * active node on the surface (|gap| <= the gap tolerance) and pushing
   * (its contact force, or each held plane's, >= -the force tolerance);
   * inactive nodes carry no force by construction. ActiveSetConstraints::
   * check_conditions().
   */
  struct ContactConditions
  {
    /// One kind of violation: how many nodes, the worst value (m or Pa)
    /// and where the worst node is (current position, m).
    struct Violation
    {
      unsigned int     nodes = 0;
      double           worst = 0;
      dealii::Point<3> where;
    };
    Violation    through;     // eligible nodes beyond the surface (m deep)
    Violation    off;         // active nodes off the surface (m)
    Violation    pulling;     // active nodes that pull (Pa)
    unsigned int outside = 0; // candidates beyond it, eligible or not
    /// Largest depth (m) of an eligible node beyond the surface; negative:
    /// the smallest clearance.
    double max_penetration = 0;

    bool
    satisfied() const
    {
      return through.nodes + off.nodes + pulling.nodes == 0;
    }
    /// "2 nodes through the obstacle by up to 0.01 mm (one at (x, y, z)
    /// mm), ...": the violations, for messages.
    std::string
    text() const;
  };

} // namespace RestShape

#endif
