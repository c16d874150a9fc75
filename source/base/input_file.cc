#include <restshape/base/input_error.h>
#include <restshape/base/input_file.h>
#include <unistd.h>

#include <filesystem>

namespace RestShape
{
  bool
  is_regular_input(const std::string &file)
  {
    std::error_code ec;
    return std::filesystem::is_regular_file(file, ec);
  }

  std::ifstream
  open_input(const std::string       &file,
             const std::string       &parameter,
             const std::string       &expected,
             const std::ios::openmode mode)
  {
    std::error_code ec;
    const auto      status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status))
      throw InputError(file, parameter, "no such file; expected " + expected);
    if (!std::filesystem::is_regular_file(status))
      throw InputError(file,
                       parameter,
                       "not a regular file (a directory, FIFO or device); "
                       "expected " +
                         expected);
    std::ifstream in;
    if (::access(file.c_str(), R_OK) == 0)
      in.open(file, mode);
    if (!in)
      throw InputError(file,
                       parameter,
                       "not a readable file; expected " + expected);
    return in;
  }
} // namespace RestShape
