#include <fcntl.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/base/interruption.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace RestShape
{
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write,
                        const std::string                         &parameter)
  {
    const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
    // An interruption removes it.
    register_temporary_file(tmp);
    struct Unregister
    {
      const std::string &tmp;
      ~Unregister()
      {
        unregister_temporary_file(tmp);
      }
    } unregister{tmp};
    {
      std::ofstream out(tmp);
      if (!out)
        throw InputError(path,
                         parameter,
                         std::string("cannot write: ") + std::strerror(errno) +
                           "; expected a writable location");
      write(out);
      out.flush();
      if (!out)
        {
          std::remove(tmp.c_str());
          throw InputError(path, parameter, "writing failed (disk full?)");
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
      {
        const std::string reason = std::strerror(errno);
        std::remove(tmp.c_str());
        throw InputError(path,
                         parameter,
                         "cannot rename into place: " + reason);
      }
  }

  void
  write_named_file_atomically(
    const std::string                              &path,
    const std::function<bool(const std::string &)> &write,
    const std::string                              &parameter,
    const std::string                              &message)
  {
    namespace fs = std::filesystem;
    const fs::path target(path);
    const fs::path tmp =
      target.parent_path() /
      (".tmp-" + std::to_string(::getpid()) + "-" + target.filename().string());
    std::error_code ec;
    register_temporary_file(tmp.string());
    struct Unregister
    {
      const std::string tmp;
      ~Unregister()
      {
        unregister_temporary_file(tmp);
      }
    } unregister{tmp.string()};
    if (!write(tmp.string()) || !fs::exists(tmp, ec))
      {
        fs::remove(tmp, ec);
        throw InputError(path, parameter, message);
      }
    fs::rename(tmp, target, ec);
    if (ec)
      {
        fs::remove(tmp, ec);
        throw InputError(path,
                         parameter,
                         "cannot rename into place: " + ec.message());
      }
  }

  void
  write_on_every_rank(const MPI_Comm               comm,
                      const std::string           &file,
                      const std::function<void()> &write,
                      const bool                   this_rank_writes)
  {
    std::string error;
    if (this_rank_writes)
      try
        {
          write();
        }
      catch (const InputError &e)
        {
          error = e.message;
        }
    for (const std::string &e : dealii::Utilities::MPI::all_gather(comm, error))
      if (!e.empty())
        throw OutputFailure(file + ": cannot write the results: " + e);
  }

  void
  claim_directory(const std::string &directory, const std::string &parameter)
  {
    const std::string lock = directory + "/.restshape.lock";
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw InputError(directory,
                       parameter,
                       std::string("cannot create its lock file: ") +
                         std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
      {
        char      owner[32] = {0};
        const int n         = ::pread(fd, owner, sizeof(owner) - 1, 0);
        ::close(fd);
        throw InputError(directory,
                         parameter,
                         "another run (process " +
                           std::string(n > 0 ? owner : "?") +
                           ") is writing its results there; expected an "
                           "output directory no other run uses");
      }
    // Held (fd left open) until this process ends.
    const std::string pid = std::to_string(::getpid());
    if (::ftruncate(fd, 0) == 0)
      {
        const ssize_t written = ::pwrite(fd, pid.c_str(), pid.size(), 0);
        (void)written;
      }
  }

  void
  ensure_writable_directory(const std::string &directory,
                            const std::string &parameter)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(directory, ec) && !fs::is_directory(directory, ec))
      throw InputError(directory,
                       parameter,
                       "exists and is not a directory; expected a directory "
                       "for the results");
    fs::create_directories(directory, ec);
    if (ec)
      throw InputError(directory,
                       parameter,
                       "cannot create the directory: " + ec.message());
    if (::access(directory.c_str(), W_OK | X_OK) != 0)
      throw InputError(directory,
                       parameter,
                       "the directory is not writable; expected a directory "
                       "where results can be written");
  }

  StagedFiles::~StagedFiles()
  {
    for (const auto &[staged, path] : files)
      {
        std::remove(staged.c_str());
        unregister_temporary_file(staged);
      }
  }

  std::string
  StagedFiles::stage(const std::string &path)
  {
    const std::filesystem::path target(path);
    const std::string           staged =
      (target.parent_path() / (".staged-" + std::to_string(::getpid()) + "-" +
                               target.filename().string()))
        .string();
    register_temporary_file(staged);
    files.emplace_back(staged, path);
    return staged;
  }

  void
  StagedFiles::commit(const std::string &parameter)
  {
    const InterruptionsDeferred all_or_none;
    for (const auto &[staged, path] : files)
      if (std::rename(staged.c_str(), path.c_str()) != 0)
        throw InputError(path,
                         parameter,
                         std::string("cannot rename into place: ") +
                           std::strerror(errno));
    for (const auto &[staged, path] : files)
      unregister_temporary_file(staged);
    files.clear();
  }
} // namespace RestShape
