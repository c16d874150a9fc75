// The machine's memory, for refusing work that cannot fit it.
#ifndef restshape_base_machine_memory_h
#define restshape_base_machine_memory_h

#include <string>

namespace RestShape
{
  /// Physical memory of this machine in bytes (0 if unknown).
  double
  physical_memory_bytes();

  /// Bytes in a GiB, for messages.
  constexpr double bytes_per_gibibyte = 1024. * 1024. * 1024.;

  /// Whether @p bytes are more than @p share (0..1) of this machine's
  /// memory; false where the memory is unknown.
  bool
  exceeds_machine_memory(double bytes, double share);

  /// @p bytes in GiB, for messages ("2.4e+05 GiB").
  std::string
  gibibytes_text(double bytes);
} // namespace RestShape

#endif
