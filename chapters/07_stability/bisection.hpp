// Chapter 7, part 3b: h_max measured. Each (K, D, method) of the sweep is a job; a job brackets the largest step
// whose run stays bounded by doubling or halving from the predicted h, then bisects the bracket geometrically.
#pragma once

#include "hmax.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace ch07 {

/// One (K, D, method) of the sweep and what was found.
struct Job {
  double K = 0, D = 0;
  std::string method;
  double guess = 0, E_eq = 0;
  double h = 0;       ///< largest h found bounded (0: none down to the floor)
  double h_fail = 0;  ///< smallest h found unbounded (0: none up to the ceiling)
  int runs = 0;
  std::string outcome;  ///< implicit Euler's probes, or why the job was skipped
  bool skipped = false;
  Prediction rest;             ///< predicted at the rest state
  double sagged_strict = NAN;  ///< predicted at the sagged equilibrium (nan: n/a)
};

/// A job whose one run costs more than `budget` (in unknowns times right-hand sides) is marked skipped, with why.
void skip_over_budget(Job& job, double h, double cost, double budget);

/// Right-hand-side evaluations per step of an explicit method (its stages).
int stages(const StabilityModel& model);

/// Measures every job that is not skipped, on sweep.threads threads, printing each result as it comes.
void measure_jobs(std::vector<Job>& jobs, const cloth::SceneParams& scene, const SweepSettings& sweep);

}  // namespace ch07
