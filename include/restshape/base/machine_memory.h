// The machine's memory, for refusing work that cannot fit it.
#ifndef restshape_base_machine_memory_h
#define restshape_base_machine_memory_h

namespace RestShape
{
  /// Physical memory of this machine in bytes (0 if unknown).
  double
  physical_memory_bytes();

  /// Bytes in a GiB, for messages.
  constexpr double bytes_per_gibibyte = 1024. * 1024. * 1024.;
} // namespace RestShape

#endif
