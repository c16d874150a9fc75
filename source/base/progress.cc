#include <restshape/base/progress.h>

#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <streambuf>
#include <thread>

namespace RestShape
{
  namespace
  {
    using Clock = std::chrono::steady_clock;

    std::mutex  phase_mutex;
    std::string current_phase = "working";
  } // namespace

  std::chrono::milliseconds
  progress_silence_from_environment()
  {
    constexpr double default_seconds = 5, least = 0.1, most = 3600;
    double           seconds = default_seconds;
    if (const char *text = std::getenv("RESTSHAPE_PROGRESS_SECONDS"))
      {
        char        *end   = nullptr;
        const double value = std::strtod(text, &end);
        if (end != text && *end == '\0' && value >= least && value <= most)
          seconds = value;
      }
    return std::chrono::milliseconds(long(seconds * 1000));
  }

  void
  set_progress_phase(const std::string &phase)
  {
    std::lock_guard<std::mutex> lock(phase_mutex);
    current_phase = phase;
  }

  /// std::cout's buffer, wrapped: it records when the last whole line
  /// went out, and lets the heartbeat write between lines.
  struct ProgressHeartbeat::Watch : public std::streambuf
  {
    Watch(std::streambuf *original, const std::chrono::milliseconds silence)
      : original(original)
      , silence(silence)
      , last_line(Clock::now())
      , thread([this]() { beat(); })
    {}

    ~Watch()
    {
      {
        std::lock_guard<std::mutex> lock(mutex);
        done = true;
      }
      wake.notify_all();
      thread.join();
    }

    int
    overflow(const int c) override
    {
      if (c == traits_type::eof())
        return traits_type::not_eof(c);
      const char ch = traits_type::to_char_type(c);
      return xsputn(&ch, 1) == 1 ? c : traits_type::eof();
    }

    std::streamsize
    xsputn(const char *s, const std::streamsize n) override
    {
      std::lock_guard<std::mutex> lock(mutex);
      const std::streamsize       written = original->sputn(s, n);
      if (n > 0)
        {
          at_line_start = s[n - 1] == '\n';
          if (at_line_start)
            last_line = Clock::now();
        }
      return written;
    }

    int
    sync() override
    {
      std::lock_guard<std::mutex> lock(mutex);
      return original->pubsync();
    }

    void
    beat()
    {
      std::unique_lock<std::mutex> lock(mutex);
      const Clock::time_point      start = Clock::now();
      while (!done)
        {
          wake.wait_until(lock, last_line + silence);
          if (done || !at_line_start || Clock::now() < last_line + silence)
            continue;
          std::string phase;
          {
            std::lock_guard<std::mutex> p(phase_mutex);
            phase = current_phase;
          }
          char line[96];
          std::snprintf(
            line,
            sizeof(line),
            " (%.0f s into the run)\n",
            std::chrono::duration<double>(Clock::now() - start).count());
          const std::string text = "  ... " + phase + line;
          original->sputn(text.data(), text.size());
          original->pubsync();
          last_line = Clock::now();
        }
    }

    std::streambuf                 *original;
    const std::chrono::milliseconds silence;
    std::mutex                      mutex;
    std::condition_variable         wake;
    Clock::time_point               last_line;
    bool                            at_line_start = true;
    bool                            done          = false;
    std::thread                     thread;
  };

  ProgressHeartbeat::ProgressHeartbeat(const bool                      active,
                                       const std::chrono::milliseconds silence)
  {
    if (!active)
      return;
    watch = std::make_unique<Watch>(std::cout.rdbuf(), silence);
    std::cout.rdbuf(watch.get());
  }

  ProgressHeartbeat::~ProgressHeartbeat()
  {
    if (!watch)
      return;
    std::cout.flush();
    std::cout.rdbuf(watch->original);
  }
} // namespace RestShape
