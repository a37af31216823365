// Chapter 10's projection study, measured (projection_runs.cpp): each program of the comparison runs a ladder of
// steps on the curtain to T, and the coarsest step reaching 1 cm and 1 mm is timed.
#pragma once

#include "model/force_field.hpp"
#include "program/timing.hpp"

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace ch10 {

inline constexpr double T = 0.5;                  ///< the curtain has swung down past the vertical [s]
inline constexpr double levels[] = {1e-2, 1e-3};  ///< the accuracies asked for [m]

// A program of the comparison: its name on the page, whether it is the book's, the steps it tries (as step counts
// over T, coarse to fine), and a run of n steps returning every particle's position at T in grid order (NaN when
// the run failed).
struct Contender {
  std::string title;
  bool book;
  std::vector<long long> steps;
  std::function<cloth::Vector(long long)> run;
};

/// One run of a ladder: its error at T, and its CPU time once it is timed.
struct Measured {
  double error = NAN;
  cloth::Timing timing;
  bool timed = false;
};

/// Every contender's runs, by step count.
using Ladders = std::vector<std::map<long long, Measured>>;

/// Each contender's ladder of steps, coarse to fine, until 1 mm at T against `truth` (every particle's position
/// in grid order): the error of every run (projection_runs.md).
Ladders run_ladders(const std::vector<Contender>& contenders, const cloth::Vector& truth, const std::string& dir,
                    const std::string& command);

/// For each level, each contender's coarsest step reaching it, timed (median of 5), and the book's fastest against
/// the fastest peer (projection_ratio.md).
void time_at_levels(const std::vector<Contender>& contenders, Ladders& measured, const std::string& dir,
                    const std::string& command);

}  // namespace ch10
