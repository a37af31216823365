// The adaptive driver of Chapter 8: from t = 0 to T with an embedded pair, each step attempted, measured in
// tolerances, accepted or tried again smaller, and the next step chosen by a controller; frames at exact times
// by interpolation, so that they never shorten a step.
#pragma once

#include "integrators/simulate.hpp"
#include "integrators/step_control.hpp"

#include <functional>
#include <vector>

namespace cloth {

/// How the step is controlled.
struct AdaptiveSettings {
  Tolerances tolerances;
  double first_step = 0;  ///< h of the first attempt [s]; 0 chooses it automatically (initial_step)
  ControllerKind controller = ControllerKind::pi;
  double safety = 0.9;     ///< aim at 0.9 of the largest acceptable step
  double min_factor = 0.2; ///< a step shrinks at most fivefold at once
  double max_factor = 10;  ///< and grows at most tenfold (HNW's DOPRI5)
  /// The floor on h: below max(min_step, 64 eps t) the run stops as failed (step_size_too_small).
  double min_step = 0;
  /// When positive, a step the error estimate accepts is refused all the same if some spring's direction turns by
  /// more than this angle [rad] across it (a spring passing near zero length turns by up to pi), unless the step
  /// is already so short that even a jump of the spring's whole force inside it, J = 2 K L0 / m, would leave a
  /// velocity error J h / 4 (Chapter 6) below atol. 0: no such check.
  double max_spring_turn = 0;
};

/// One attempted step, for steps.dat and the figures.
struct StepAttempt {
  double t;      ///< where it started
  double h;      ///< its size
  double error;  ///< its error in tolerances (error_norm)
  bool accepted;
};

/// What an adaptive run produced: the fixed-step RunResult (steps = accepted steps) and the step statistics.
struct AdaptiveResult : RunResult {
  long long accepted = 0, rejected = 0;
  long long refused_for_turn = 0;  ///< rejected steps the estimate accepted but a spring turned too far across
  double smallest_step = 0, largest_step = 0;  ///< over the accepted steps
  std::vector<StepAttempt> attempts;             ///< every attempt, when recording
};

/// Called after every attempt with the attempt and the state it started from (for studies of the hard case).
using AttemptObserver = std::function<void(const StepAttempt&, const Vector& x, const Vector& v)>;

/// Runs the scene's initial state to run.t_end (stopping between two attempts when run.stop is raised). With
/// `record`, energy.dat's samples are taken at every accepted
/// step and the frames at t = k T / frames by cubic Hermite interpolation of the positions between the ends of the
/// step that contains them (from x and v = x' at both ends: no extra evaluation, error O(h^4)). Without recording
/// the step loop allocates nothing.
AdaptiveResult adaptive_simulate(EmbeddedRungeKutta& rk, const RunSettings& run, const AdaptiveSettings& settings,
                                 bool record = true, const AttemptObserver& observer = {});

/// The same from the state (x0, v0) instead of the scene's initial state.
AdaptiveResult adaptive_simulate(EmbeddedRungeKutta& rk, const Vector& x0, const Vector& v0, const RunSettings& run,
                                 const AdaptiveSettings& settings, bool record = true,
                                 const AttemptObserver& observer = {});

/// The largest angle [rad] by which the direction of a spring at least `min_rest_length` long at rest turns
/// between the free positions x0 and x1.
double largest_spring_turn(const Scene& scene, const Vector& x0, const Vector& x1, double min_rest_length = 0);

/// The cubic Hermite interpolant of positions at t0 + theta h between (x0, v0) and (x1, v1), into `out`.
void hermite_positions(double theta, double h, const Vector& x0, const Vector& v0, const Vector& x1, const Vector& v1,
                       Vector& out);

}  // namespace cloth
