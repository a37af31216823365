// How the book times code, said once: the calling thread's processor time, read beside the wall clock, over repeated
// runs summarised by the fastest, the median and the slowest (their spread is printed with every timing).
#pragma once

#include <functional>
#include <limits>

namespace cloth {

/// Processor seconds the calling thread has used (CLOCK_THREAD_CPUTIME_ID). Unlike the wall clock it does not count
/// the time the thread waited for a core while other processes ran, so it is the clock to compare across runs on
/// a shared machine; it stops while the thread sleeps or waits for input, which the timed code never does.
[[nodiscard]] double thread_cpu_seconds();

/// Processor seconds used by every thread of the process (CLOCK_PROCESS_CPUTIME_ID): for the programs that run
/// independent studies side by side (program/parallel_runs.hpp), where one thread's clock would miss the others.
[[nodiscard]] double process_cpu_seconds();

/// Wall-clock seconds since an arbitrary fixed origin (std::chrono::steady_clock: never set back).
[[nodiscard]] double wall_seconds();

/// How to repeat a timed body.
struct TimingPlan {
  int runs = 5;     ///< timed runs summarised below
  int warmup = 0;   ///< untimed runs first (caches, page faults, lazily built tables)
  int repeat = 1;   ///< calls per timed run, for a body too short for the clock; the times are per call
  /// Processor seconds after which no further timed run starts (at least one always runs): for a ladder of
  /// settings whose slow rungs a budget would otherwise make last minutes. The Timing says how many ran.
  double budget = std::numeric_limits<double>::infinity();
};

/// The seconds per call of repeated runs: thread processor time (the figure to compare) and wall time.
struct Timing {
  double fastest_cpu = 0;   ///< the run least disturbed by other processes
  double median_cpu = 0;    ///< the middle run (the upper middle for an even count)
  double slowest_cpu = 0;   ///< with fastest_cpu, the spread of the timings
  double fastest_wall = 0;
  double median_wall = 0;
  int runs = 0;             ///< timed runs made (fewer than the plan's when its budget ran out)
};

/// Times `body` as `plan` says. No input or output belongs inside the body: it would be timed too.
[[nodiscard]] Timing time_runs(const std::function<void()>& body, const TimingPlan& plan = {});

}  // namespace cloth
