// The book's timing rule (program/timing.hpp) does what its documentation says: the body is called warmup + runs x
// repeat times, the summary is ordered fastest <= median <= slowest, a budget stops the runs once spent, and the
// thread clock counts work, not waiting.
#include "program/timing.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

TEST_CASE("time_runs calls the body warmup + runs x repeat times and orders its summary") {
  int calls = 0;
  volatile double sink = 0;
  const cloth::Timing t = cloth::time_runs(
      [&] {
        ++calls;
        for (int k = 0; k < 20000; ++k) sink = sink + std::sqrt(static_cast<double>(k));
      },
      {.runs = 5, .warmup = 2, .repeat = 3});
  CHECK(calls == 2 * 3 + 5 * 3);
  CHECK(t.runs == 5);
  CHECK(t.fastest_cpu > 0);
  CHECK(t.fastest_cpu <= t.median_cpu);
  CHECK(t.median_cpu <= t.slowest_cpu);
  CHECK(t.fastest_wall <= t.median_wall);
}

TEST_CASE("the thread clock does not count sleeping; the wall clock does") {
  const cloth::Timing t =
      cloth::time_runs([] { std::this_thread::sleep_for(std::chrono::milliseconds(20)); }, {.runs = 1});
  CHECK(t.fastest_wall >= 0.019);
  CHECK(t.fastest_cpu < 0.005);
}

TEST_CASE("time_runs refuses a plan with no timed run") {
  CHECK_THROWS_AS((void)cloth::time_runs([] {}, {.runs = 0}), std::invalid_argument);
  CHECK_THROWS_AS((void)cloth::time_runs([] {}, {.runs = 1, .warmup = 0, .repeat = 0}), std::invalid_argument);
}

TEST_CASE("a budget stops the timed runs once spent, after at least one") {
  int calls = 0;
  volatile double sink = 0;
  const auto body = [&] {
    ++calls;
    for (int k = 0; k < 20000; ++k) sink = sink + std::sqrt(static_cast<double>(k));
  };
  // A budget of zero: the first run spends it, so exactly one runs.
  const cloth::Timing once = cloth::time_runs(body, {.runs = 5, .budget = 0});
  CHECK(calls == 1);
  CHECK(once.runs == 1);
  CHECK(once.fastest_cpu == once.slowest_cpu);
  // A budget no run can spend: every planned run is made.
  calls = 0;
  const cloth::Timing all = cloth::time_runs(body, {.runs = 4, .budget = 1e9});
  CHECK(calls == 4);
  CHECK(all.runs == 4);
}
