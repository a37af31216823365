// The fixed-step driver shared by every simulating chapter.
#include "integrators/simulate.hpp"

#include "base/format_number.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace cloth {

const char* run_status_name(RunStatus status) {
  switch (status) {
    case RunStatus::ok: return "ok";
    case RunStatus::diverged: return "diverged";
    case RunStatus::step_failed: return "step_failed";
    case RunStatus::interrupted: return "interrupted";
  }
  return "unknown";
}

long long step_count(const RunSettings& settings) {
  return static_cast<long long>(std::ceil(settings.t_end / settings.dt * (1 - 1e-12)));
}

int frame_count(const RunSettings& settings) {
  return static_cast<int>(std::min<long long>(settings.frames, step_count(settings)));
}

double divergence_radius(const Scene& scene, double t_end) {
  const Grid& g = scene.grid();
  const double L = std::hypot((g.M - 1) * g.d, (g.N - 1) * g.d);
  const auto& p = scene.params();
  return 10.0 * (L + std::abs(p.initial_velocity_z) * t_end + 0.5 * p.gravity * t_end * t_end) + 1.0;
}

std::string divergence_reason(const Vector& x, const Vector& v, double radius) {
  const double r2 = radius * radius;
  // The driver asks after every step and the answer is nearly always "sane": one pass without branches says so
  // (a NaN or an infinity makes the total non-finite), and only a state that fails it is searched again, by the
  // loop below, which alone decides and words the answer.
  double largest = 0, total = 0;
  for (Eigen::Index k = 0; k + 2 < x.size(); k += 3) {
    const double d2 = x[k] * x[k] + x[k + 1] * x[k + 1] + x[k + 2] * x[k + 2];
    const double s2 = v[k] * v[k] + v[k + 1] * v[k + 1] + v[k + 2] * v[k + 2];
    largest = std::max(largest, d2);
    total += d2 + s2;
  }
  if (largest <= r2 && std::isfinite(total)) return {};
  for (Eigen::Index k = 0; k + 2 < x.size(); k += 3) {
    const double d2 = x[k] * x[k] + x[k + 1] * x[k + 1] + x[k + 2] * x[k + 2];
    const double s2 = v[k] * v[k] + v[k + 1] * v[k + 1] + v[k + 2] * v[k + 2];
    if (!std::isfinite(d2) || !std::isfinite(s2)) return "a non-finite position or velocity";
    if (d2 > r2)
      return "a particle " + format_number(std::sqrt(d2), 3) + " m from the origin, beyond the bound R = " +
             format_number(radius, 3) + " m";
  }
  return {};
}

void stop_run(RunResult& result, RunStatus status, StepFailureKind kind, long long step, double t,
              std::string reason) {
  result.status = status;
  result.failure = kind;
  result.failed_step = step;
  result.failed_t = t;
  result.reason = std::move(reason);
  result.message = run_status_name(status);
  if (status == RunStatus::step_failed) result.message.append(" (").append(step_failure_name(kind)).append(")");
  result.message += " at step " + std::to_string(step) + ", t = " + format_number(t) + " s: " + result.reason;
}

namespace {

// A stop request (SIGINT, SIGTERM, see program/interrupt.hpp) that the run should honour before its next step.
bool stop_requested(const RunSettings& settings) {
  return settings.stop != nullptr && settings.stop->load(std::memory_order_relaxed) != 0;
}

// Ends the run as interrupted after `steps_done` steps, at time `t`.
void stop_interrupted(RunResult& result, long long steps_done, double t) {
  result.status = RunStatus::interrupted;
  result.message = "interrupted after step " + std::to_string(steps_done) + ", t = " + format_number(t) + " s";
}

}  // namespace

RunResult simulate(Stepper& stepper, const RunSettings& settings, bool record) {
  ForceField& field = stepper.field();
  const Scene& scene = field.scene();
  RunResult result;
  result.x = scene.initial_positions();
  result.v = scene.initial_velocities();
  const double h = settings.dt;
  const double T = settings.t_end;
  const long long steps = step_count(settings);
  const int frames = frame_count(settings);
  const double radius = divergence_radius(scene, T);

  // Every recording buffer is sized here, so the step loop below allocates nothing.
  std::size_t frames_recorded = 0;
  const auto record_frame = [&](double t) {
    Frame& frame = result.frames[frames_recorded++];
    frame.t = t;
    scene.all_positions(result.x, frame.positions);
  };
  if (record) {
    result.energy.reserve(static_cast<std::size_t>(steps) + 1);
    result.frames.assign(static_cast<std::size_t>(frames) + 1, Frame{0.0, Vector(3 * scene.particle_count())});
    result.energy.push_back({0.0, field.energy(result.x, result.v)});
    record_frame(0.0);
  }
  int next_frame = 1;

  Vector x_prev = result.x, v_prev = result.v;
  stepper.reset_counters();
  const auto start = std::chrono::steady_clock::now();
  // [simulation_loop]
  for (long long k = 0; k < steps; ++k) {
    const double t0 = static_cast<double>(k) * h;
    const double t1 = k + 1 == steps ? T : static_cast<double>(k + 1) * h;
    // A stop request (SIGINT, SIGTERM) ends the run between two steps, with every output up to here whole.
    if (stop_requested(settings)) {
      stop_interrupted(result, k, t0);
      break;
    }
    x_prev = result.x;
    v_prev = result.v;
    // Every step is exactly h (t1 - t0 would differ from h by rounding from step to step); only a last step
    // that T shortens is not.
    const double step_h = k + 1 == steps && std::abs(T - t0 - h) > 1e-9 * h ? T - t0 : h;
    if (!stepper.step(step_h, result.x, result.v)) {
      stop_run(result, RunStatus::step_failed, stepper.failure().kind, k + 1, t1, stepper.failure().reason);
      break;
    }
    if (std::string why = divergence_reason(result.x, result.v, radius); !why.empty()) {
      stop_run(result, RunStatus::diverged, StepFailureKind::none, k + 1, t1, std::move(why));
      result.x = x_prev;  // keep the last sane state
      result.v = v_prev;
      break;
    }
    result.steps = k + 1;
    result.t = t1;
    if (record) {
      result.energy.push_back({t1, field.energy(result.x, result.v)});
      if (next_frame <= frames && t1 >= T * next_frame / frames - 1e-9 * h) {
        record_frame(t1);
        ++next_frame;
      }
    }
    if (settings.progress) settings.progress(k + 1, steps, false);
  }
  // [simulation_loop]
  if (settings.progress) settings.progress(result.steps, steps, true);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.frames.resize(frames_recorded);
  result.counters = stepper.counters();
  if (result.status == RunStatus::ok) result.message = "ok";
  return result;
}

}  // namespace cloth
