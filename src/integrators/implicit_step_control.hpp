// Step-size control for an embedded diagonally implicit pair (Chapter 9): Chapter 8's controllers on the embedded
// error estimate, and a step that shrinks when Newton fails instead of stopping the run.
#pragma once

#include "integrators/diagonally_implicit_runge_kutta.hpp"
#include "integrators/simulate.hpp"
#include "integrators/step_control.hpp"

namespace cloth {

/// The controller's settings.
struct StepControl {
  double tolerance = 1e-3;   ///< err = max_k |e_k| / (tol (1 + |y_k|)) over positions and velocities; accept err <= 1
  ControllerKind controller = ControllerKind::pi;  ///< Chapter 8's PI controller unless told
  double safety = 0.9;       ///< the new step aims at err = safety^(q+1), not at the edge
  double max_growth = 2.0;   ///< the step grows at most by this factor...
  double max_shrink = 0.2;   ///< ...and shrinks at least to this one after a rejection
  double newton_shrink = 0.25;  ///< the factor after a step Newton could not solve
  double min_step = 1e-9;    ///< below this h [s] the run fails with step_size_too_small
};

/// What a controlled run did besides the fixed-step result.
struct ControlledRun {
  RunResult result;
  long long rejected_steps = 0;   ///< steps rejected by the error test
  long long newton_failures = 0;  ///< steps Newton could not solve, retried smaller
  double smallest_step = 0, largest_step = 0;  ///< accepted steps' range [s]
};

/// Runs the scene's initial state to settings.t_end with steps chosen by the embedded error estimate, starting
/// from h = settings.dt, by Chapter 8's StepController with k = q + 1, q the lower order of the pair (the PI
/// controller of Gustafsson 1991 unless control.controller says elementary), its factor kept within
/// [max_shrink, max_growth]. A step Newton cannot solve is retried at newton_shrink times its length, and the
/// step after it does not grow. Steps are shortened to land on the frame times. The stepper's tableau must have
/// embedded weights.
ControlledRun simulate_controlled(DiagonallyImplicitRungeKutta& stepper, const RunSettings& settings,
                                  const StepControl& control);

}  // namespace cloth
