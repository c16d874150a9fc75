// The machine's memory, for refusing work that cannot fit it.
#ifndef restshape_base_machine_memory_h
#define restshape_base_machine_memory_h

#include <string>

namespace RestShape
{
  /// Physical memory of this machine in bytes (0 if unknown).
  double
  physical_memory_bytes();

  /// The memory a run may take and where that limit comes from.
  struct MemoryLimit
  {
    double      bytes; // 0 if unknown
    std::string where; // "this machine's memory", "... cgroup", "ulimit"

    /// "the memory limit of this process's cgroup, 8 GiB".
    std::string
    text() const;
  };

  /// The smallest of the physical memory, the memory cgroup's limit
  /// (v2 memory.max, v1 memory.limit_in_bytes) and ulimit -v / -d.
  MemoryLimit
  available_memory();

  /// Bytes in a GiB, for messages.
  constexpr double bytes_per_gibibyte = 1024. * 1024. * 1024.;

  /// Whether @p bytes are more than @p share (0..1) of the available
  /// memory (available_memory()); false where it is unknown.
  bool
  exceeds_machine_memory(double bytes, double share);

  /// @p bytes in GiB, for messages ("2.4e+05 GiB").
  std::string
  gibibytes_text(double bytes);
} // namespace RestShape

#endif
