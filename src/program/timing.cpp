// Implements the book's one timing rule (timing.hpp): thread processor time beside the wall clock, summarised over
// repeated runs by the fastest, the median and the slowest.
#include "program/timing.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <stdexcept>
#include <vector>

namespace cloth {

namespace {

double read_clock(clockid_t id) {
  timespec ts{};
  clock_gettime(id, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double median_of(std::vector<double> t) {
  const auto middle = t.begin() + static_cast<long>(t.size() / 2);
  std::nth_element(t.begin(), middle, t.end());
  return *middle;
}

}  // namespace

double thread_cpu_seconds() { return read_clock(CLOCK_THREAD_CPUTIME_ID); }

double process_cpu_seconds() { return read_clock(CLOCK_PROCESS_CPUTIME_ID); }

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Timing time_runs(const std::function<void()>& body, const TimingPlan& plan) {
  if (plan.runs < 1 || plan.repeat < 1 || plan.warmup < 0)
    throw std::invalid_argument("time_runs: runs and repeat must be at least 1, warmup at least 0");
  for (int k = 0; k < plan.warmup; ++k)
    for (int r = 0; r < plan.repeat; ++r) body();
  std::vector<double> cpu, wall;
  double spent = 0;
  for (int k = 0; k < plan.runs && (k == 0 || spent < plan.budget); ++k) {
    const double w0 = wall_seconds();
    const double c0 = thread_cpu_seconds();
    for (int r = 0; r < plan.repeat; ++r) body();
    const double used = thread_cpu_seconds() - c0;
    spent += used;
    cpu.push_back(used / plan.repeat);
    wall.push_back((wall_seconds() - w0) / plan.repeat);
  }
  Timing t;
  t.runs = static_cast<int>(cpu.size());
  t.fastest_cpu = *std::min_element(cpu.begin(), cpu.end());
  t.slowest_cpu = *std::max_element(cpu.begin(), cpu.end());
  t.median_cpu = median_of(cpu);
  t.fastest_wall = *std::min_element(wall.begin(), wall.end());
  t.median_wall = median_of(wall);
  return t;
}

}  // namespace cloth
