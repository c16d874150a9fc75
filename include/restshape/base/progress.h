// A line on the screen at least every few seconds: while a long phase
// (a factorisation, a Krylov solve, meshing) prints nothing, a heartbeat
// says what is running and for how long.
#ifndef restshape_base_progress_h
#define restshape_base_progress_h

#include <chrono>
#include <memory>
#include <string>

namespace RestShape
{
  /**
   * While it lives, std::cout is watched: after @p silence without a
   * line, one line "  ... PHASE: running for N s" (the phase last set by
   * set_progress_phase()), then again every @p silence. Only whole lines
   * are watched: a line being written is never cut. Inactive (nothing
   * watched or printed) if @p active is false (MPI ranks but the first).
   */
  class ProgressHeartbeat
  {
  public:
    ProgressHeartbeat(bool active, std::chrono::milliseconds silence);
    ~ProgressHeartbeat();

  private:
    struct Watch;
    std::unique_ptr<Watch> watch;
  };

  /// The heartbeat's silence: RESTSHAPE_PROGRESS_SECONDS if it is a
  /// number from 0.1 to 3600, else 5 s.
  std::chrono::milliseconds
  progress_silence_from_environment();

  /// What is running now, for the heartbeat ("Newton step 3 at 0.5 of
  /// the load: linear solve"). Thread-safe; cheap enough for every
  /// iteration of a solver.
  void
  set_progress_phase(const std::string &phase);
} // namespace RestShape

#endif
