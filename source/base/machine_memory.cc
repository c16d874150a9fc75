#include <restshape/base/machine_memory.h>
#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <limits>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// A cgroup limit file's value in bytes ("max" or unreadable: none).
    double
    limit_in_file(const std::string &path)
    {
      std::ifstream in(path);
      double        value = 0;
      if (!(in >> value) || !(value > 0))
        return std::numeric_limits<double>::infinity();
      // cgroup v1 writes "no limit" as the largest page-aligned int64.
      return value >= 1e18 ? std::numeric_limits<double>::infinity() : value;
    }

    /// The memory cgroup's limit of this process (v2, then v1).
    double
    cgroup_limit_bytes()
    {
      double        limit = std::numeric_limits<double>::infinity();
      std::ifstream groups("/proc/self/cgroup");
      std::string   line;
      while (std::getline(groups, line))
        {
          const auto colon = line.find(':');
          const auto path  = line.find(':', colon + 1);
          if (colon == std::string::npos || path == std::string::npos)
            continue;
          const std::string controllers =
            line.substr(colon + 1, path - colon - 1);
          const std::string where = line.substr(path + 1);
          if (controllers.empty())
            {
              limit = std::min(limit,
                               limit_in_file("/sys/fs/cgroup" + where +
                                             "/memory.max"));
              limit =
                std::min(limit, limit_in_file("/sys/fs/cgroup/memory.max"));
            }
          else if (controllers == "memory")
            {
              limit = std::min(limit,
                               limit_in_file("/sys/fs/cgroup/memory" + where +
                                             "/memory.limit_in_bytes"));
              limit =
                std::min(limit,
                         limit_in_file(
                           "/sys/fs/cgroup/memory/memory.limit_in_bytes"));
            }
        }
      return limit;
    }

    /// ulimit -v and -d of this process.
    double
    rlimit_bytes()
    {
      double limit = std::numeric_limits<double>::infinity();
      for (const int resource : {RLIMIT_AS, RLIMIT_DATA})
        {
          rlimit r;
          if (getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
            limit = std::min(limit, double(r.rlim_cur));
        }
      return limit;
    }
  } // namespace

  double
  physical_memory_bytes()
  {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page  = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? double(pages) * double(page) : 0.;
  }

  MemoryLimit
  available_memory()
  {
    MemoryLimit  m{physical_memory_bytes(), "this machine's memory"};
    const double cgroup = cgroup_limit_bytes();
    if (cgroup < m.bytes || m.bytes == 0)
      m = {cgroup, "the memory limit of this process's cgroup"};
    const double rlimit = rlimit_bytes();
    if (rlimit < m.bytes || m.bytes == 0)
      m = {rlimit, "the address-space limit (ulimit -v / -d)"};
    return m;
  }

  std::string
  MemoryLimit::text() const
  {
    return where + ", " + gibibytes_text(bytes);
  }

  bool
  exceeds_machine_memory(const double bytes, const double share)
  {
    const double memory = available_memory().bytes;
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
