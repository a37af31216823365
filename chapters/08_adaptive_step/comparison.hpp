// Chapter 8's comparison with Boost.Odeint: the reference the errors are measured against, the runs of each side
// (the registry's pairs, and odeint's controlled steppers on a plain right-hand side and on the project's forces),
// and what the page quotes of them.
#pragma once

#include "integrators/simulate.hpp"
#include "model/scene.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace ch08 {

using LongState = std::vector<long double>;

/// The reference state at T and its credential (comparison_runs.cpp).
struct Reference {
  LongState y;                       ///< (x, v) of the free particles at T
  double tolerance = 0;              ///< rtol = atol of both runs
  long long steps = 0, check_steps = 0;
  double agreement = 0;              ///< distance of the check run from it at T [m]
};
Reference long_double_reference(const cloth::Scene& scene, double T, double tolerance);

/// Largest distance of a free particle from the reference at T [m].
template <class X>
double position_error(const X& x, const LongState& ref) {
  double worst = 0;
  for (std::size_t k = 0; k + 2 < ref.size() / 2; k += 3) {
    long double d2 = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const long double d = static_cast<long double>(x[static_cast<Eigen::Index>(k + c)]) - ref[k + c];
      d2 += d * d;
    }
    worst = std::max(worst, static_cast<double>(std::sqrt(d2)));
  }
  return worst;
}

/// One configuration of one side at one tolerance: its error at T, its timing and its evaluations.
struct Row {
  std::string series;  ///< project_rms, project_max, project_rms_elementary, project_rms_turn, odeint_plain,
                       ///< odeint_project_forces
  std::string method;  ///< the pair: a registry name, or odeint's stepper
  double tol = 0;
  double error = 0;
  cloth::Timing timing;  ///< thread CPU seconds of the whole run, over `runs` repetitions
  long long evaluations = 0;
};

/// What each side runs, and how often each run is timed.
struct ComparisonPlan {
  cloth::RunSettings run;           ///< the horizon T in run.t_end
  std::vector<double> tolerances;   ///< rtol = atol, the same for every configuration of both sides
  int runs = 5;                     ///< timed repetitions of each run
};

/// The registry's pairs (every pair with each norm, and two variants of dopri5) at every tolerance.
std::vector<Row> project_runs(const cloth::Scene& scene, const LongState& ref, const ComparisonPlan& plan);
/// Odeint's controlled dopri5 and cash_karp54, each on the plain right-hand side and on the project's forces.
std::vector<Row> odeint_runs(const cloth::Scene& scene, const LongState& ref, const ComparisonPlan& plan);

/// The series and pairs each side's fair best is taken over: the same two pairs with the same norm (odeint's
/// error checker takes the largest component), at the same tolerances.
bool in_fair_project_set(const Row& r);

/// reference.md: the reference's credential, written as soon as it is known (comparison_fragments.cpp).
void write_reference(const std::string& dir, const Reference& ref, double T, const std::string& command);
/// work_precision.dat, levels.dat, spring_turn.md, evaluation_cost.md, levels.md and tries.md
/// (comparison_fragments.cpp).
void write_comparison(const std::string& dir, const std::vector<Row>& rows, const Reference& reference,
                      const ComparisonPlan& plan, const cloth::SceneParams& scene, const std::string& command);

}  // namespace ch08
