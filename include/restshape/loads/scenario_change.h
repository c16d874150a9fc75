// What a scenario changes of the loads after the rest shape, as the load
// terms see it.
#ifndef restshape_loads_scenario_change_h
#define restshape_loads_scenario_change_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/base/region.h>

#include <map>
#include <string>
#include <vector>

namespace RestShape
{
  /**
   * A scenario entry that a load term declares (in subsection Scenario and
   * every Scenario NAME): one number or a vector 'x, y, z', or empty for
   * no change where @p optional.
   */
  struct ScenarioEntry
  {
    std::string  name;          // "Surface pressure"
    std::string  default_value; // "" or "0, 0, 0"
    std::string  help;          // what it changes, its unit
    unsigned int n_values = 1;  // 1 or 3
    /// The scene's parameter ("Section/Entry") that must be set for the
    /// entry to act (empty: none); a scenario that gives the entry without
    /// it is an input error.
    std::string needs = "";
  };

  /**
   * The situation a scenario describes (Scenario subsection): the head
   * turned (gravity rotated), the fluid drained to a level, an opening of
   * the skull, and the values the load terms' own scenario entries were
   * given. Each load term changes its own load from it
   * (LoadTerm::change_load()).
   */
  struct ScenarioChange
  {
    /// Gravity rotated: the rotation and its angles about x, y, z.
    dealii::Tensor<2, 3> rotation;
    dealii::Tensor<1, 3> rotation_degrees;
    bool                 turned = false;
    /// The fluid drained to a level (a point of its new free surface, m).
    bool             has_fluid_level = false;
    dealii::Point<3> fluid_level;
    /// An opening of the skull (none: not defined).
    Region opening;
    /// The given values of the terms' scenario entries, by entry name
    /// (an entry left empty is absent).
    std::map<std::string, std::vector<double>> values;

    /// Whether @p name was given a value.
    bool
    has(const std::string &name) const
    {
      return values.count(name) > 0;
    }
    /// The value of the entry @p name, which must have been given.
    double
    value(const std::string &name) const
    {
      return values.at(name)[0];
    }
    /// The vector value of @p name, or zero where it was not given.
    dealii::Tensor<1, 3>
    vector(const std::string &name) const
    {
      const auto it = values.find(name);
      if (it == values.end())
        return {};
      return dealii::Tensor<1, 3>(
        {it->second[0], it->second[1], it->second[2]});
    }
  };
} // namespace RestShape

#endif
