// Signal handlers that leave a consistent output directory.
#include <fcntl.h>
#include <restshape/base/interruption.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace RestShape
{
  namespace
  {
    /// Temporary files written at the same time (one per thread writing).
    constexpr unsigned int max_temporaries = 32;
    /// Longest path and summary kept for the handler.
    constexpr std::size_t max_path = 4096, max_summary = 16384;

    /// A slot is free (0), being filled (1) or holds a path (2).
    struct Slot
    {
      std::atomic<int> state{0};
      char             path[max_path];
    };
    std::array<Slot, max_temporaries> temporaries;

    /// The summary written on an interruption, one text per signal.
    struct InterruptedSummary
    {
      std::atomic<bool> set{false};
      char              path[max_path], tmp[max_path];
      char              text[3][max_summary];
      std::size_t       length[3] = {0, 0, 0};
    } summary;

    constexpr int signals[3] = {SIGINT, SIGTERM, SIGHUP};

    /// Sections during which an interruption waits (see
    /// InterruptionsDeferred), and the signal that arrived meanwhile.
    std::atomic<int> deferring{0};
    std::atomic<int> pending_signal{0};

    int
    signal_index(const int sig)
    {
      for (int i = 0; i < 3; ++i)
        if (signals[i] == sig)
          return i;
      return 0;
    }

    void
    write_all(const int fd, const char *data, std::size_t size)
    {
      while (size > 0)
        {
          const ssize_t n = ::write(fd, data, size);
          if (n <= 0)
            return;
          data += n;
          size -= n;
        }
    }

    void
    leave_consistent_and_exit(const int sig)
    {
      for (Slot &slot : temporaries)
        if (slot.state.load() == 2)
          ::unlink(slot.path);
      if (summary.set.load())
        {
          const int i = signal_index(sig);
          const int fd =
            ::open(summary.tmp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
          if (fd >= 0)
            {
              write_all(fd, summary.text[i], summary.length[i]);
              ::close(fd);
              ::rename(summary.tmp, summary.path);
            }
          // One line on stderr, from the process that writes the summary
          // (rank 0 under MPI).
          static const char *lines[3] = {
            "Interrupted by SIGINT (signal 2): temporary files removed, "
            "summary.json says so.\n",
            "Interrupted by SIGTERM (signal 15): temporary files removed, "
            "summary.json says so.\n",
            "Interrupted by SIGHUP (signal 1): temporary files removed, "
            "summary.json says so.\n"};
          write_all(2, lines[i], std::strlen(lines[i]));
        }
      ::_exit(128 + sig);
    }

    extern "C" void
    on_interrupt(const int sig)
    {
      if (deferring.load() > 0)
        {
          pending_signal = sig;
          // The section may have ended between the test and the store:
          // then nobody else will see the signal.
          if (deferring.load() > 0)
            return;
        }
      leave_consistent_and_exit(sig);
    }

    bool
    copy(char *target, const std::string &text, const std::size_t size)
    {
      if (text.size() + 1 > size)
        return false;
      std::memcpy(target, text.c_str(), text.size() + 1);
      return true;
    }
  } // namespace

  void
  install_interrupt_handlers()
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    for (const int sig : signals)
      sigaddset(&action.sa_mask, sig);
    for (const int sig : signals)
      sigaction(sig, &action, nullptr);
    // A closed stdout (restshape ... | head) is not a reason to lose the
    // results: writes to it fail (EPIPE) instead of killing the run, and
    // main() reports the lost screen output at the end.
    std::signal(SIGPIPE, SIG_IGN);
  }

  InterruptionsDeferred::InterruptionsDeferred()
  {
    ++deferring;
  }

  InterruptionsDeferred::~InterruptionsDeferred()
  {
    if (--deferring == 0)
      if (const int sig = pending_signal.exchange(0); sig != 0)
        leave_consistent_and_exit(sig);
  }

  void
  set_interrupted_summary(const std::string &summary_path,
                          const std::string &json_before_failure)
  {
    summary.set          = false;
    const char *names[3] = {"SIGINT", "SIGTERM", "SIGHUP"};
    for (int i = 0; i < 3; ++i)
      {
        const std::string text =
          json_before_failure +
          "\n  \"interrupted\": true,\n  \"failure\": " + "\"interrupted by " +
          names[i] + " (signal " + std::to_string(signals[i]) + ")\"\n}\n";
        if (!copy(summary.text[i], text, max_summary))
          return;
        summary.length[i] = text.size();
      }
    if (copy(summary.path, summary_path, max_path) &&
        copy(summary.tmp,
             summary_path + ".tmp-" + std::to_string(::getpid()),
             max_path))
      summary.set = true;
  }

  void
  register_temporary_file(const std::string &path)
  {
    if (path.size() >= max_path)
      return;
    for (Slot &slot : temporaries)
      {
        int free = 0;
        if (slot.state.compare_exchange_strong(free, 1))
          {
            copy(slot.path, path, max_path);
            slot.state = 2;
            return;
          }
      }
  }

  void
  unregister_temporary_file(const std::string &path)
  {
    for (Slot &slot : temporaries)
      if (slot.state.load() == 2 && path == slot.path)
        {
          slot.state = 0;
          return;
        }
  }
} // namespace RestShape
