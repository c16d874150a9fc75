// The version of RestShape and the git revision it was built from.
#ifndef restshape_base_version_h
#define restshape_base_version_h

#include <string>

namespace RestShape
{
  /// The release version ("0.9.0"; the project's version in CMakeLists.txt).
  const char *
  version();

  /// The git revision of the build (git describe --always --dirty), or
  /// "unknown" outside a git checkout.
  const char *
  git_revision();

  /// "@p program 0.9.0 (git 80084c8abcde), deal.II 9.4.1": what --version
  /// prints.
  std::string
  version_text(const std::string &program);
} // namespace RestShape

#endif
