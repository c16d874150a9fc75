#include <restshape/base/machine_memory.h>
#include <unistd.h>

#include <sstream>

namespace RestShape
{
  double
  physical_memory_bytes()
  {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page  = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? double(pages) * double(page) : 0.;
  }

  bool
  exceeds_machine_memory(const double bytes, const double share)
  {
    const double memory = physical_memory_bytes();
    return memory > 0 && bytes > share * memory;
  }

  std::string
  gibibytes_text(const double bytes)
  {
    std::ostringstream text;
    text.precision(3);
    text << bytes / bytes_per_gibibyte << " GiB";
    return text.str();
  }
} // namespace RestShape
