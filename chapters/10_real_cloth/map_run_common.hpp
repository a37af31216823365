// What every run of Chapter 10's map shares (map_runs.cpp and map_sundials_runs.cpp): the frame interval, the
// timing rule, and the peers' ODE systems on the plain or the book's force loop.
#pragma once

#include "map_runs.hpp"
#include "peer_systems.hpp"

#include "program/timing.hpp"

#include <cmath>
#include <functional>
#include <memory>

namespace ch10::map_detail {

constexpr double frame_interval = 1.0 / 60;

/// Runs `body` (which fills a MapRun) and times it; a run shorter than 0.2 s is repeated twice and the fastest
/// time kept (on a shared machine the fastest run is the least disturbed).
inline MapRun timed(const std::function<MapRun()>& body) {
  double start = cloth::thread_cpu_seconds();
  MapRun run = body();
  run.seconds = cloth::thread_cpu_seconds() - start;
  for (int k = 0; k < 2 && run.ok && run.seconds < 0.2; ++k) {
    start = cloth::thread_cpu_seconds();
    body();
    run.seconds = std::min(run.seconds, cloth::thread_cpu_seconds() - start);
  }
  return run;
}

/// How many frames of `interval` fit in T.
inline long long frame_count(double interval, double T) { return std::llround(T / interval); }

inline std::unique_ptr<OdeSystem> system_for(const cloth::Scene& scene, Forces forces) {
  if (forces == Forces::plain) return std::make_unique<PlainSystem>(scene.params(), true);
  return std::make_unique<CoreSystem>(scene, true);
}

inline cloth::Frame frame_of(const OdeSystem& system, const std::vector<double>& y, double t) { return {t, system.positions(y)}; }

}  // namespace ch10::map_detail
