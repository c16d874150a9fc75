// The version line of every tool.
#include <deal.II/base/config.h>

#include <restshape/base/version.h>

namespace RestShape
{
  const char *
  version()
  {
    return RESTSHAPE_VERSION;
  }

  std::string
  version_text(const std::string &program)
  {
    return program + " " + version() + " (git " + git_revision() +
           "), deal.II " + DEAL_II_PACKAGE_VERSION;
  }
} // namespace RestShape
