// Input files opened only once they are known to be regular files.
#ifndef restshape_base_input_file_h
#define restshape_base_input_file_h

#include <fstream>
#include <string>

namespace RestShape
{
  /// Whether @p file is a regular file (not a FIFO, device or directory,
  /// which would block a reader or never end).
  bool
  is_regular_input(const std::string &file);

  /**
   * @p file opened for reading once it is known to be a readable regular
   * file; otherwise InputError naming @p file and @p parameter: "no such
   * file", "not a regular file (a directory, FIFO or device)" or "not a
   * readable file", each followed by "; expected " @p expected.
   */
  std::ifstream
  open_input(const std::string &file,
             const std::string &parameter,
             const std::string &expected,
             std::ios::openmode mode = std::ios::in);
} // namespace RestShape

#endif
