// What an interruption does inside and outside an InterruptionsDeferred
// section, in child processes: outside, the process ends at once with
// 128 + the signal and writes the interrupted summary; inside, it goes on
// to the end of the (outermost) section first, whichever thread the signal
// reaches, and then ends the same way.
#include <restshape/base/interruption.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "checks.h"

using namespace RestShape;
using namespace checks;
namespace fs = std::filesystem;

namespace
{
  const fs::path directory =
    fs::temp_directory_path() /
    ("restshape_interruptions_" + std::to_string(::getpid()));

  void
  touch(const std::string &name)
  {
    std::ofstream(directory / name) << name << '\n';
  }

  std::string
  contents(const std::string &name)
  {
    std::ifstream      in(directory / name);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// Run @p body in a child process with the handlers installed and the
  /// interrupted summary set; return its exit code (-1 if it did not exit).
  template <typename F>
  int
  in_child(const F &body)
  {
    fs::remove_all(directory);
    fs::create_directories(directory);
    const pid_t pid = ::fork();
    if (pid == 0)
      {
        install_interrupt_handlers();
        set_interrupted_summary((directory / "summary.json").string(),
                                "{\n  \"converged\": false,");
        body();
        touch("finished");
        ::_exit(0);
      }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  bool
  says_interrupted_by(const std::string &name)
  {
    return contents("summary.json")
             .find("\"failure\": \"interrupted by " + name) !=
           std::string::npos;
  }
} // namespace

int
main()
{
  int code = in_child([] {
    std::raise(SIGTERM);
    touch("after_signal");
  });
  expect(code == 128 + SIGTERM && !fs::exists(directory / "after_signal") &&
           says_interrupted_by("SIGTERM"),
         "outside a section, SIGTERM ends the run at once (exit 143) with "
         "the interrupted summary");

  code = in_child([] {
    {
      const InterruptionsDeferred section;
      std::raise(SIGINT);
      touch("in_section");
    }
    touch("after_section");
  });
  expect(code == 128 + SIGINT && fs::exists(directory / "in_section") &&
           !fs::exists(directory / "after_section") &&
           says_interrupted_by("SIGINT"),
         "inside a section, SIGINT waits for its end, then ends the run "
         "(exit 130) with the interrupted summary");

  code = in_child([] {
    const InterruptionsDeferred outer;
    {
      const InterruptionsDeferred inner;
      std::raise(SIGHUP);
    }
    touch("after_inner");
  });
  expect(code == 128 + SIGHUP && fs::exists(directory / "after_inner"),
         "nested sections: the signal waits for the outermost one");

  code = in_child([] {
    const InterruptionsDeferred section;
    // A process-directed signal from another thread: delivered to any
    // thread that does not block it.
    std::thread([] { ::kill(::getpid(), SIGTERM); }).join();
    ::usleep(20000);
    touch("in_section");
  });
  expect(code == 128 + SIGTERM && fs::exists(directory / "in_section") &&
           !fs::exists(directory / "finished") &&
           says_interrupted_by("SIGTERM"),
         "a signal sent from another thread waits for the section too");

  code = in_child([] { const InterruptionsDeferred section; });
  expect(code == 0 && fs::exists(directory / "finished") &&
           !fs::exists(directory / "summary.json"),
         "a section without a signal changes nothing");

  fs::remove_all(directory);
  return failures == 0 ? 0 : 1;
}
