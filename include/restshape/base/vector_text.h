// A vector as text for reports: "(x, y, z)" with four significant digits.
#ifndef restshape_base_vector_text_h
#define restshape_base_vector_text_h

#include <deal.II/base/tensor.h>

#include <iomanip>
#include <sstream>
#include <string>

namespace RestShape
{
  /// "(x, y, z)" of @p v in units of @p unit (each component divided by
  /// it), four significant digits, no negative zero.
  inline std::string
  vector_text(const dealii::Tensor<1, 3> &v, const double unit = 1)
  {
    std::ostringstream out;
    out << std::setprecision(4) << '(' << v[0] / unit + 0. << ", "
        << v[1] / unit + 0. << ", " << v[2] / unit + 0. << ')';
    return out.str();
  }
} // namespace RestShape

#endif
