// The controlled driver: propose, solve, estimate, accept or retry.
#include "integrators/implicit_step_control.hpp"

#include "base/format_number.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace cloth {

namespace {
// max_k |e_k| / (tol (1 + |y_k|)) over both halves of the state.
double scaled_error(const Vector& ex, const Vector& ev, const Vector& x, const Vector& v, double tol) {
  double err = 0;
  for (Eigen::Index k = 0; k < x.size(); ++k)
    err = std::max({err, std::abs(ex[k]) / (1 + std::abs(x[k])), std::abs(ev[k]) / (1 + std::abs(v[k]))});
  return err / tol;
}
}  // namespace

ControlledRun simulate_controlled(DiagonallyImplicitRungeKutta& stepper, const RunSettings& settings,
                                  const StepControl& control) {
  ForceField& field = stepper.field();
  const Scene& scene = field.scene();
  ControlledRun run;
  RunResult& result = run.result;
  result.x = scene.initial_positions();
  result.v = scene.initial_velocities();
  const double T = settings.t_end;
  const double radius = divergence_radius(scene, T);
  const int q = std::min(stepper.tableau().method.order, stepper.tableau().method.embedded_order);
  result.energy.reserve(4096);
  result.frames.reserve(static_cast<std::size_t>(settings.frames) + 1);
  result.energy.push_back({0.0, field.energy(result.x, result.v)});
  result.frames.push_back({0.0, Vector(3 * scene.particle_count())});
  scene.all_positions(result.x, result.frames.back().positions);
  int next_frame = 1;
  Vector x = result.x, v = result.v;
  double t = 0, h = settings.dt;
  run.smallest_step = INFINITY;
  StepController controller(control.controller, q + 1, control.safety, control.max_shrink, control.max_growth);
  bool after_newton_failure = false;
  stepper.reset_counters();
  const auto start = std::chrono::steady_clock::now();
  // [controlled_loop]
  while (t < T * (1 - 1e-12)) {
    // Land on the next frame time (and on T) rather than step over it.
    const double frame_time = T * next_frame / settings.frames;
    const bool to_frame = t + h >= frame_time * (1 - 1e-12);
    const double step_h = to_frame ? frame_time - t : h;
    if (step_h < control.min_step) {
      result.status = RunStatus::step_failed;
      result.message = "step failed at step " + std::to_string(result.steps + 1) + ", t = " + format_number(t, 6) +
                       ": step_size_too_small: h = " + format_number(step_h, 3) + " s is below the floor " +
                       format_number(control.min_step, 3) + " s";
      break;
    }
    x = result.x;
    v = result.v;
    if (!stepper.step(step_h, x, v)) {
      // Newton could not solve the stages: the step retreats, whatever the error estimate last said.
      ++run.newton_failures;
      h = step_h * control.newton_shrink;
      after_newton_failure = true;
      continue;
    }
    const double err = scaled_error(stepper.error_positions(), stepper.error_velocities(), x, v, control.tolerance);
    const bool accepted = err <= 1;  // false for a NaN estimate too
    const double factor = controller.factor(std::isfinite(err) ? err : INFINITY, accepted);
    if (!accepted) {
      ++run.rejected_steps;
      h = step_h * factor;
      continue;
    }
    if (const std::string why = divergence_reason(x, v, radius); !why.empty()) {
      result.status = RunStatus::diverged;
      result.message = "diverged at step " + std::to_string(result.steps + 1) + ", t = " +
                       format_number(t + step_h, 6) + " s: " + why;
      break;
    }
    t = to_frame ? frame_time : t + step_h;
    result.x = x;
    result.v = v;
    ++result.steps;
    result.t = t;
    run.smallest_step = std::min(run.smallest_step, step_h);
    run.largest_step = std::max(run.largest_step, step_h);
    result.energy.push_back({t, field.energy(x, v)});
    if (to_frame) {
      result.frames.push_back({t, Vector(3 * scene.particle_count())});
      scene.all_positions(x, result.frames.back().positions);
      ++next_frame;
    }
    // The controller's proposal for the next step; a step shortened to meet a frame does not shrink it, and the
    // step after a Newton failure does not grow.
    const double proposal = step_h * (after_newton_failure ? std::min(factor, 1.0) : factor);
    after_newton_failure = false;
    h = to_frame && step_h < h ? std::max(h, proposal) : proposal;
  }
  // [controlled_loop]
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.counters = stepper.counters();
  if (result.status == RunStatus::ok) result.message = "ok";
  if (result.steps == 0) run.smallest_step = 0;
  return run;
}

}  // namespace cloth
