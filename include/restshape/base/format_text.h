// printf-style text of up to three numbers, for messages and progress lines.
#ifndef restshape_base_format_text_h
#define restshape_base_format_text_h

#include <cstdio>
#include <string>

namespace RestShape
{
  /// @p fmt (printf conversions for doubles only) with @p a, @p b, @p c;
  /// at most 255 characters.
  inline std::string
  format_text(const char  *fmt,
              const double a,
              const double b = 0,
              const double c = 0)
  {
    char buffer[256];
    std::snprintf(buffer, sizeof(buffer), fmt, a, b, c);
    return buffer;
  }
} // namespace RestShape

#endif
