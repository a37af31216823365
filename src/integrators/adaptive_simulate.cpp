// The adaptive step loop: attempt, measure, accept or reject, choose the next h.
#include "integrators/adaptive_simulate.hpp"

#include "base/format_number.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace cloth {

void hermite_positions(double theta, double h, const Vector& x0, const Vector& v0, const Vector& x1, const Vector& v1,
                       Vector& out) {
  const double t2 = theta * theta, t3 = t2 * theta;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + theta, h01 = 3 * t2 - 2 * t3, h11 = t3 - t2;
  out.noalias() = h00 * x0 + (h10 * h) * v0 + h01 * x1 + (h11 * h) * v1;
}

double largest_spring_turn(const Scene& scene, const Vector& x0, const Vector& x1, double min_rest_length) {
  const Eigen::VectorXd& rest = scene.rest_positions();  // the pinned slots' positions, after the free ones
  const int free = scene.free_count();
  const auto position = [&](const Vector& x, int slot) -> Eigen::Vector3d {
    return slot < free ? Eigen::Vector3d(x.segment<3>(3 * slot)) : Eigen::Vector3d(rest.segment<3>(3 * slot));
  };
  double largest_cos_turn = 1;  // the smallest cosine of a turn
  for (const Spring& s : scene.springs().springs) {
    if (s.rest_length < min_rest_length) continue;
    const Eigen::Vector3d d0 = position(x0, s.p) - position(x0, s.q), d1 = position(x1, s.p) - position(x1, s.q);
    const double n = d0.norm() * d1.norm();
    if (n > 0) largest_cos_turn = std::min(largest_cos_turn, d0.dot(d1) / n);
  }
  return std::acos(std::clamp(largest_cos_turn, -1.0, 1.0));
}

AdaptiveResult adaptive_simulate(EmbeddedRungeKutta& rk, const RunSettings& run, const AdaptiveSettings& settings,
                                 bool record, const AttemptObserver& observer) {
  const Scene& scene = rk.field().scene();
  return adaptive_simulate(rk, scene.initial_positions(), scene.initial_velocities(), run, settings, record, observer);
}

AdaptiveResult adaptive_simulate(EmbeddedRungeKutta& rk, const Vector& x0, const Vector& v0, const RunSettings& run,
                                 const AdaptiveSettings& settings, bool record, const AttemptObserver& observer) {
  ForceField& field = rk.field();
  const Scene& scene = field.scene();
  AdaptiveResult result;
  result.x = x0;
  result.v = v0;
  Vector& x = result.x;
  Vector& v = result.v;
  const double T = run.t_end;
  const double radius = divergence_radius(scene, T);
  const double eps = std::numeric_limits<double>::epsilon();

  Vector frame_x(x.size());
  std::size_t frame_count = 0;
  const auto record_frame = [&](double t, const Vector& positions) {
    Frame& frame = result.frames[frame_count++];
    frame.t = t;
    scene.all_positions(positions, frame.positions);
  };
  if (record) {
    result.energy.reserve(1024);
    result.attempts.reserve(1024);
    result.frames.assign(static_cast<std::size_t>(run.frames) + 1, Frame{0.0, Vector(3 * scene.particle_count())});
    result.energy.push_back({0.0, field.energy(x, v)});
    record_frame(0.0, x);
  }
  int next_frame = 1;

  rk.reset_counters();
  rk.restart();
  StepController controller(settings.controller, rk.estimate_order(), settings.safety, settings.min_factor,
                            settings.max_factor);
  const auto start = std::chrono::steady_clock::now();
  double t = 0;
  double h = settings.first_step > 0 ? settings.first_step : initial_step(rk, x, v, settings.tolerances);
  result.smallest_step = std::numeric_limits<double>::infinity();
  // [adaptive_loop]
  while (t < T) {
    // A stop request (SIGINT, SIGTERM) ends the run between two attempts, with every output up to here whole.
    if (run.stop != nullptr && run.stop->load(std::memory_order_relaxed) != 0) {
      result.status = RunStatus::interrupted;
      result.message = "interrupted after step " + std::to_string(result.steps) + ", t = " + format_number(t) + " s";
      break;
    }
    const bool last = t + h >= T * (1 - 4 * eps);  // the step that ends the run lands on T exactly
    const double step = last ? T - t : h;
    const double floor = std::max(settings.min_step, 64 * eps * std::max(t, T));
    if (step < floor && !last) {
      stop_run(result, RunStatus::step_failed, StepFailureKind::step_size_too_small, result.steps + 1, t + step,
               "step size too small: h = " + format_number(step, 3) + " s is below the floor " +
                   format_number(floor, 3) + " s, after " + std::to_string(result.rejected) + " rejected steps");
      break;
    }
    rk.attempt(step, x, v);
    const double err =
        error_norm(rk.error_x(), rk.error_v(), x, v, rk.candidate_x(), rk.candidate_v(), settings.tolerances);
    bool accepted = err <= 1.0;
    double turn = 0;
    if (accepted && settings.max_spring_turn > 0) {
      // Springs whose whole-force jump J h / 4 = K L0 h / (2 m) could exceed atol (all of them on long steps).
      const double min_rest = 2 * scene.params().mass * settings.tolerances.atol / (scene.params().stiffness * step);
      turn = largest_spring_turn(scene, x, rk.candidate_x(), min_rest);
      if (turn > settings.max_spring_turn) accepted = false, ++result.refused_for_turn;
    }
    const StepAttempt attempt{t, step, err, accepted};
    if (record) result.attempts.push_back(attempt);
    if (observer) observer(attempt, x, v);
    // A step refused for its turn shrinks in proportion (the turn is about proportional to h); the controller
    // sees it as a rejection, so the step does not grow right after.
    double factor = controller.factor(err, accepted);
    if (err <= 1.0 && !accepted) factor = std::clamp(0.9 * settings.max_spring_turn / turn, 0.2, 0.9);
    if (!accepted) {  // the state is untouched: try again from it with a smaller step
      ++result.rejected;
      h = step * factor;
      continue;
    }
    if (const std::string why = divergence_reason(rk.candidate_x(), rk.candidate_v(), radius); !why.empty()) {
      stop_run(result, RunStatus::diverged, StepFailureKind::none, result.steps + 1, t + step, why);
      break;
    }
    // Frames inside (t, t + step] from the step's two ends, before the candidate replaces the state.
    if (record) {
      while (next_frame <= run.frames && T * next_frame / run.frames <= t + step * (1 + 4 * eps)) {
        const double t_frame = T * next_frame / run.frames;
        const double theta = std::min(1.0, (t_frame - t) / step);
        hermite_positions(theta, step, x, v, rk.candidate_x(), rk.candidate_v(), frame_x);
        record_frame(t_frame, frame_x);
        ++next_frame;
      }
    }
    rk.accept(x, v);
    t = last ? T : t + step;
    ++result.steps;
    ++result.accepted;
    result.t = t;
    result.smallest_step = std::min(result.smallest_step, step);
    result.largest_step = std::max(result.largest_step, step);
    if (record) result.energy.push_back({t, field.energy(x, v)});
    h = (last ? h : step) * factor;
  }
  // [adaptive_loop]
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (result.accepted == 0) result.smallest_step = 0;
  result.frames.resize(frame_count);
  result.counters = rk.counters();
  if (result.status == RunStatus::ok) result.message = "ok";
  return result;
}

}  // namespace cloth
