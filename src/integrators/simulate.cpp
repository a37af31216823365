// The fixed-step driver shared by every simulating chapter.
#include "integrators/simulate.hpp"

#include "base/format_number.hpp"

#include <chrono>
#include <cmath>

namespace cloth {

double divergence_radius(const Scene& scene, double t_end) {
  const Grid& g = scene.grid();
  const double L = std::hypot((g.M - 1) * g.d, (g.N - 1) * g.d);
  const auto& p = scene.params();
  return 10.0 * (L + std::abs(p.initial_velocity_z) * t_end + 0.5 * p.gravity * t_end * t_end) + 1.0;
}

std::string divergence_reason(const Vector& x, const Vector& v, double radius) {
  const double r2 = radius * radius;
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

RunResult simulate(Stepper& stepper, const RunSettings& settings, bool record) {
  ForceField& field = stepper.field();
  const Scene& scene = field.scene();
  RunResult result;
  result.x = scene.initial_positions();
  result.v = scene.initial_velocities();
  const double h = settings.dt;
  const double T = settings.t_end;
  const auto steps = static_cast<long long>(std::ceil(T / h * (1 - 1e-12)));
  const double radius = divergence_radius(scene, T);

  // Every recording buffer is sized here, so the step loop below allocates nothing.
  std::size_t frame_count = 0;
  const auto record_frame = [&](double t) {
    Frame& frame = result.frames[frame_count++];
    frame.t = t;
    scene.all_positions(result.x, frame.positions);
  };
  if (record) {
    result.energy.reserve(static_cast<std::size_t>(steps) + 1);
    result.frames.assign(static_cast<std::size_t>(settings.frames) + 1, Frame{0.0, Vector(3 * scene.particle_count())});
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
    x_prev = result.x;
    v_prev = result.v;
    // Every step is exactly h (t1 - t0 would differ from h by rounding from step to step); only a last step
    // that T shortens is not.
    const double step_h = k + 1 == steps && std::abs(T - t0 - h) > 1e-9 * h ? T - t0 : h;
    if (!stepper.step(step_h, result.x, result.v)) {
      result.status = RunStatus::step_failed;
      result.failure = stepper.failure().kind;
      result.message = "step failed at step " + std::to_string(k + 1) + ", t = " + std::to_string(t1) + ": " +
                       stepper.failure().reason;
      break;
    }
    if (const std::string why = divergence_reason(result.x, result.v, radius); !why.empty()) {
      result.status = RunStatus::diverged;
      result.message = "diverged at step " + std::to_string(k + 1) + ", t = " + format_number(t1) + " s: " + why;
      result.x = x_prev;  // keep the last sane state
      result.v = v_prev;
      break;
    }
    result.steps = k + 1;
    result.t = t1;
    if (record) {
      result.energy.push_back({t1, field.energy(result.x, result.v)});
      if (next_frame <= settings.frames && t1 >= T * next_frame / settings.frames - 1e-9 * h) {
        record_frame(t1);
        ++next_frame;
      }
    }
  }
  // [simulation_loop]
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.frames.resize(frame_count);
  result.counters = stepper.counters();
  if (result.status == RunStatus::ok) result.message = "ok";
  return result;
}

}  // namespace cloth
