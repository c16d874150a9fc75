// The contact conditions of a state, in words.
#include <restshape/base/units.h>
#include <restshape/solver/active_set_conditions.h>

#include <cstdio>

namespace RestShape
{
  namespace
  {
    using Violation = ContactConditions::Violation;

    std::string
    describe(const Violation &v,
             const char      *what,
             const double     scale,
             const char      *unit)
    {
      if (v.nodes == 0)
        return "";
      char buffer[256];
      std::snprintf(buffer,
                    sizeof(buffer),
                    "%u node%s %s by up to %.3g %s (the worst at (%.2f, "
                    "%.2f, %.2f) mm)",
                    v.nodes,
                    v.nodes == 1 ? "" : "s",
                    what,
                    v.worst * scale,
                    unit,
                    mm_per_m * v.where[0],
                    mm_per_m * v.where[1],
                    mm_per_m * v.where[2]);
      return buffer;
    }
  } // namespace

  std::string
  ContactConditions::text() const
  {
    std::string result;
    for (const std::string &part :
         {describe(through, "through the obstacle", mm_per_m, "mm"),
          describe(off, "active but off the obstacle", mm_per_m, "mm"),
          describe(pulling, "pulling on the obstacle", 1, "Pa")})
      if (!part.empty())
        result += (result.empty() ? "" : "; ") + part;
    return result.empty() ? "the contact conditions hold" : result;
  }

} // namespace RestShape
