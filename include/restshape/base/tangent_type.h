// Which tangent a Newton step uses (Discretization/Tangent): what the
// material laws compute and the solver's tangent strategy chooses.
#ifndef restshape_base_tangent_type_h
#define restshape_base_tangent_type_h

namespace RestShape
{
  enum class TangentType
  {
    consistent,
    projected,
    adaptive,
    warped
  };
} // namespace RestShape

#endif
