// What the parts that follow a solve (contact, reports) read of its state,
// without the solver that produces it.
#ifndef restshape_fem_state_reader_h
#define restshape_fem_state_reader_h

#include <restshape/base/linear_algebra_types.h>

namespace RestShape
{
  /// The state of a solve on a Discretization: the displacement from the
  /// mesh geometry and the rest displacement X_rest - X_mesh (ghosted, m).
  class StateReader
  {
  public:
    virtual ~StateReader() = default;

    virtual const VectorType &
    displacement() const = 0;
    virtual const VectorType &
    rest_displacement() const = 0;
  };
} // namespace RestShape

#endif
