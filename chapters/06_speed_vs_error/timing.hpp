// How Chapter 6 times code: in-process with std::chrono::steady_clock, a warm-up first, then the median of
// several runs, with no I/O inside the timed region (the median shrugs off the odd run another process slows).
// Beside the wall clock it reads the thread's CPU clock, which does not count the time the thread waited for a
// core: on a shared machine that second number is the one to compare across runs.
#pragma once

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace ch06 {

struct Seconds {
  double wall = 0;  ///< median steady_clock seconds per call
  double cpu = 0;   ///< median thread CPU seconds per call
};

inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// Median seconds of `body()` over `runs` timed runs after `warmup` untimed ones. When one call is too short for
/// the clock, each timed run repeats the body `repeat` times and the time is divided by it.
template <class Body>
Seconds median_seconds(Body&& body, int runs = 7, int warmup = 1, int repeat = 1) {
  using clock = std::chrono::steady_clock;
  for (int k = 0; k < warmup; ++k)
    for (int r = 0; r < repeat; ++r) body();
  std::vector<double> wall(static_cast<std::size_t>(runs)), cpu(wall.size());
  for (std::size_t k = 0; k < wall.size(); ++k) {
    const auto t0 = clock::now();
    const double c0 = thread_cpu_seconds();
    for (int r = 0; r < repeat; ++r) body();
    cpu[k] = (thread_cpu_seconds() - c0) / repeat;
    wall[k] = std::chrono::duration<double>(clock::now() - t0).count() / repeat;
  }
  const auto median = [](std::vector<double>& t) {
    std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
    return t[t.size() / 2];
  };
  return {median(wall), median(cpu)};
}

}  // namespace ch06
