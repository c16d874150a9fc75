#include <fcntl.h>
#include <restshape/base/input_error.h>
#include <restshape/mesh/child_reader.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace RestShape
{
  namespace
  {
    /// What the child sends: 'M' and the mesh, or 'E' and a message.
    class Writer
    {
    public:
      void
      put(const void *data, const std::size_t n)
      {
        bytes.append(static_cast<const char *>(data), n);
      }
      template <typename T>
      void
      put(const T value)
      {
        put(&value, sizeof(T));
      }
      void
      put_points(const std::vector<dealii::Point<3>> &points)
      {
        put<std::uint64_t>(points.size());
        for (const auto &p : points)
          for (unsigned int d = 0; d < 3; ++d)
            put<double>(p[d]);
      }
      /// Write everything to @p fd (a pipe).
      void
      send(const int fd) const
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

    private:
      std::string bytes;
    };

    class Reader
    {
    public:
      explicit Reader(std::string bytes)
        : bytes(std::move(bytes))
      {}
      template <typename T>
      T
      get()
      {
        T value{};
        if (position + sizeof(T) > bytes.size())
          throw std::runtime_error("short message from the child");
        std::memcpy(&value, bytes.data() + position, sizeof(T));
        position += sizeof(T);
        return value;
      }
      std::vector<dealii::Point<3>>
      get_points()
      {
        std::vector<dealii::Point<3>> points(checked_count(24));
        for (auto &p : points)
          for (unsigned int d = 0; d < 3; ++d)
            p[d] = get<double>();
        return points;
      }
      /// A count of items of at least @p item_bytes each that fits the rest.
      std::size_t
      checked_count(const std::size_t item_bytes)
      {
        const auto n = get<std::uint64_t>();
        if (n > (bytes.size() - position) / item_bytes)
          throw std::runtime_error("short message from the child");
        return n;
      }
      std::string
      rest() const
      {
        return bytes.substr(position);
      }

    private:
      std::string bytes;
      std::size_t position = 0;
    };

    void
    serialize(const MeshDescription &mesh, Writer &out)
    {
      out.put<char>('M');
      out.put_points(mesh.vertices);
      out.put<std::uint64_t>(mesh.cells.size());
      for (const auto &cell : mesh.cells)
        {
          out.put<std::uint32_t>(cell.vertices.size());
          for (const unsigned int v : cell.vertices)
            out.put<std::uint32_t>(v);
          out.put<std::uint32_t>(cell.material_id);
        }
      out.put_points(mesh.targets);
      out.put<std::uint64_t>(mesh.mass_ratios.size());
      for (const double r : mesh.mass_ratios)
        out.put<double>(r);
    }

    MeshDescription
    deserialize(Reader &in)
    {
      MeshDescription mesh;
      mesh.vertices = in.get_points();
      mesh.cells.resize(in.checked_count(8));
      for (auto &cell : mesh.cells)
        {
          cell.vertices.resize(in.get<std::uint32_t>());
          for (auto &v : cell.vertices)
            v = in.get<std::uint32_t>();
          cell.material_id = in.get<std::uint32_t>();
        }
      mesh.targets = in.get_points();
      mesh.mass_ratios.resize(in.checked_count(8));
      for (double &r : mesh.mass_ratios)
        r = in.get<double>();
      return mesh;
    }

    /// The child: read, send, end without running any destructor.
    [[noreturn]] void
    run_child(const std::function<MeshDescription()> &read, const int fd)
    {
      // It dies of its signal, whatever handlers the parent installed (a
      // fuzzer's would report the parent's input as a crash).
      for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
        std::signal(sig, SIG_DFL);
      // Its own messages (glibc's "double free or corruption") stay off
      // the terminal: the parent reports the crash in one line.
      ::setenv("LIBC_FATAL_STDERR_", "1", 1);
      const int null = ::open("/dev/null", O_WRONLY);
      if (null >= 0)
        ::dup2(null, STDERR_FILENO);
      Writer out;
      try
        {
          serialize(read(), out);
        }
      catch (const InputError &e)
        {
          out = Writer();
          out.put<char>('E');
          out.put(e.message.data(), e.message.size());
        }
      catch (const std::exception &e)
        {
          out = Writer();
          out.put<char>('E');
          const std::string what = e.what();
          out.put(what.data(), what.size());
        }
      out.send(fd);
      ::close(fd);
      _exit(0);
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
  } // namespace

  MeshDescription
  read_in_child_process(const std::function<MeshDescription()> &read,
                        const std::string                      &file,
                        const std::string                      &parameter,
                        const std::string                      &expected)
  {
    int fds[2];
    if (::pipe(fds) != 0)
      return read();
    const pid_t pid = fork();
    if (pid < 0)
      {
        ::close(fds[0]);
        ::close(fds[1]);
        return read();
      }
    if (pid == 0)
      {
        ::close(fds[0]);
        run_child(read, fds[1]);
      }
    ::close(fds[1]);
    std::string bytes = receive(fds[0]);
    ::close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
      ;
    const auto crashed = [&](const std::string &how) {
      return InputError(file,
                        parameter,
                        "the reader crashed on this file (" + how +
                          "); expected " + expected);
    };
    if (WIFSIGNALED(status))
      throw crashed("signal " + std::to_string(WTERMSIG(status)) + ", " +
                    strsignal(WTERMSIG(status)));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty())
      throw crashed("exit code " + std::to_string(WEXITSTATUS(status)));
    Reader in(std::move(bytes));
    try
      {
        if (in.get<char>() == 'E')
          throw InputError(file, parameter, in.rest());
        return deserialize(in);
      }
    catch (const std::runtime_error &e)
      {
        if (dynamic_cast<const InputError *>(&e))
          throw;
        throw crashed("its result was cut short");
      }
  }
} // namespace RestShape
