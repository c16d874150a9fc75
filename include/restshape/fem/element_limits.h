// The largest elements RestShape builds (Q2 hexahedra), for fixed-size
// buffers on hot paths.
#ifndef restshape_fem_element_limits_h
#define restshape_fem_element_limits_h

namespace RestShape
{
  /// Shape functions of the scalar element: 27 for Q2 hexahedra.
  constexpr unsigned int max_scalar_functions = 27;
  /// Of the vector element (three components).
  constexpr unsigned int max_dofs_per_cell = 3 * max_scalar_functions;
} // namespace RestShape

#endif
