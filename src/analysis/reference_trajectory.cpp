// The reference motion of Chapter 10's measures (see reference_trajectory.hpp).
#include "analysis/reference_trajectory.hpp"

#include "integrators/adaptive_simulate.hpp"
#include "integrators/embedded_runge_kutta.hpp"
#include "integrators/method_registry.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cloth {

ReferenceTrajectory reference_trajectory(ForceField& field, const Vector& x0, const Vector& v0, double T, int frames,
                                         double tolerance, const std::atomic<int>* stop) {
  const Scene& scene = field.scene();
  EmbeddedRungeKutta rk(field, embedded_tableau_from_argument("dopri5"));
  AdaptiveSettings settings;
  settings.tolerances = {tolerance, tolerance, NormKind::max};
  ReferenceTrajectory ref;
  Vector x = x0, v = v0;
  const auto record = [&](double t) {
    ref.frames.push_back({t, Vector(3 * scene.particle_count())});
    scene.all_positions(x, ref.frames.back().positions);
    ref.energy.push_back(field.energy(x, v));
  };
  record(0);
  ref.smallest_step = T;
  for (int k = 1; k <= frames; ++k) {
    // The system is autonomous, so each interval is a run from t = 0 of length T / frames that ends on the frame.
    RunSettings run;
    run.t_end = T / frames;
    run.frames = 1;
    run.stop = stop;
    const AdaptiveResult r = adaptive_simulate(rk, x, v, run, settings, false);
    if (r.status == RunStatus::interrupted) break;
    if (r.status != RunStatus::ok)
      throw std::runtime_error("reference: dopri5 failed in frame " + std::to_string(k) + ": " + r.message);
    x = r.x;
    v = r.v;
    ref.steps += r.accepted;
    ref.rejected += r.rejected;
    ref.smallest_step = std::min(ref.smallest_step, r.smallest_step);
    settings.first_step = r.largest_step;  // the next interval starts where this one left off
    record(T * k / frames);
  }
  return ref;
}

}  // namespace cloth
