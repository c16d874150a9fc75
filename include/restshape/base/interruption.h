// What a run leaves when it is interrupted (SIGINT, SIGTERM, SIGHUP): no
// temporary file, and a summary.json that says so.
#ifndef restshape_base_interruption_h
#define restshape_base_interruption_h

#include <string>

namespace RestShape
{
  /**
   * Install handlers for SIGINT, SIGTERM and SIGHUP that remove every
   * temporary file being written (write_file_atomically() registers them),
   * write the summary given to set_interrupted_summary() (if any) and end
   * the process with exit code 128 + the signal. Everything the handlers do
   * is async-signal-safe (unlink, open, write, rename, _exit).
   */
  void
  install_interrupt_handlers();

  /**
   * A section that an interruption does not cut: a signal that arrives
   * while one exists is acted on (as install_interrupt_handlers() says)
   * when the last one ends. For the moves between two consistent states of
   * an output directory (the previous result removed and the new run's
   * summary written; staged files renamed into place), whichever thread
   * the signal is delivered to.
   */
  class InterruptionsDeferred
  {
  public:
    InterruptionsDeferred();
    ~InterruptionsDeferred();
    InterruptionsDeferred(const InterruptionsDeferred &) = delete;
    InterruptionsDeferred &
    operator=(const InterruptionsDeferred &) = delete;
  };

  /**
   * On an interruption, write @p json_before_failure followed by
   * `"failure": "interrupted by SIGTERM (signal 15)"` and `}` to
   * @p summary_path (through a temporary file and a rename).
   * @p json_before_failure is a JSON object without its closing brace
   * whose last member ends with a comma.
   */
  void
  set_interrupted_summary(const std::string &summary_path,
                          const std::string &json_before_failure);

  /// A temporary file that an interruption removes (up to a fixed number
  /// at once; more are not removed).
  void
  register_temporary_file(const std::string &path);
  void
  unregister_temporary_file(const std::string &path);
} // namespace RestShape

#endif
