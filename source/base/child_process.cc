#include <fcntl.h>
#include <restshape/base/child_process.h>
#include <restshape/base/input_error.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>

// In a sanitizer's build (the fuzz targets), the sanitizer's death
// callback; absent (null) otherwise.
extern "C" void
__sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

namespace RestShape
{
  namespace
  {
    /// The first byte of the child's message: a result or an error.
    constexpr char result_tag = 'R';
    constexpr char error_tag  = 'E';

    /// Write all of @p bytes to @p fd (a pipe).
    void
    send(const int fd, const std::string &bytes)
    {
      std::size_t done = 0;
      while (done < bytes.size())
        {
          const ssize_t n =
            ::write(fd, bytes.data() + done, bytes.size() - done);
          if (n < 0 && errno == EINTR)
            continue;
          if (n <= 0)
            return;
          done += n;
        }
    }

    std::string
    receive(const int fd)
    {
      std::string bytes;
      char        buffer[1 << 16];
      for (;;)
        {
          const ssize_t n = ::read(fd, buffer, sizeof(buffer));
          if (n < 0 && errno == EINTR)
            continue;
          if (n <= 0)
            break;
          bytes.append(buffer, n);
        }
      return bytes;
    }

    /// The child: work, send, end without running any destructor.
    [[noreturn]] void
    run_child(const std::function<std::string()> &work, const int fd)
    {
      // It dies of its signal, whatever handlers the parent installed (a
      // fuzzer's would report the parent's input as a crash).
      for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
        std::signal(sig, SIG_DFL);
      // Nor does a sanitizer's report here run the fuzzer's death callback,
      // which would save the parent's input as a crash of its own.
      if (__sanitizer_set_death_callback != nullptr)
        __sanitizer_set_death_callback(nullptr);
      // Its own messages (glibc's "double free or corruption") stay off
      // the terminal: the parent reports the crash in one line.
      ::setenv("LIBC_FATAL_STDERR_", "1", 1);
      const int null = ::open("/dev/null", O_WRONLY);
      if (null >= 0)
        ::dup2(null, STDERR_FILENO);
      std::string message;
      try
        {
          message = result_tag + work();
        }
      catch (const InputError &e)
        {
          message = error_tag + e.message;
        }
      catch (const std::exception &e)
        {
          message = error_tag + std::string(e.what());
        }
      send(fd, message);
      ::close(fd);
      _exit(0);
    }

    /// The bytes @p work returns, computed in a forked child (here without
    /// fork()); @p crashed makes the error of a child that died.
    std::string
    child_bytes(const std::function<std::string()>                   &work,
                const std::string                                    &file,
                const std::string                                    &parameter,
                const std::function<InputError(const std::string &)> &crashed)
    {
      int fds[2];
      if (::pipe(fds) != 0)
        return work();
      const pid_t pid = fork();
      if (pid < 0)
        {
          ::close(fds[0]);
          ::close(fds[1]);
          return work();
        }
      if (pid == 0)
        {
          ::close(fds[0]);
          run_child(work, fds[1]);
        }
      ::close(fds[1]);
      std::string bytes = receive(fds[0]);
      ::close(fds[0]);
      int status = 0;
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
      if (WIFSIGNALED(status))
        throw crashed("signal " + std::to_string(WTERMSIG(status)) + ", " +
                      strsignal(WTERMSIG(status)));
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty())
        throw crashed("exit code " + std::to_string(WEXITSTATUS(status)));
      if (bytes[0] == error_tag)
        throw InputError(file, parameter, bytes.substr(1));
      if (bytes[0] != result_tag)
        throw crashed("its result was cut short");
      return bytes.substr(1);
    }
  } // namespace

  void
  run_in_child_process(const std::function<std::string()>      &work,
                       const std::function<void(ByteReader &)> &parse,
                       const std::string                       &file,
                       const std::string                       &parameter,
                       const std::string                       &expected)
  {
    const auto crashed = [&](const std::string &how) {
      return InputError(file,
                        parameter,
                        "the reader crashed on this file (" + how +
                          "); expected " + expected);
    };
    ByteReader in(child_bytes(work, file, parameter, crashed));
    try
      {
        parse(in);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::runtime_error &)
      {
        throw crashed("its result was cut short");
      }
  }
} // namespace RestShape
