// Chapter 10's study of cloth that moves, measured: a scene's reference motion at every frame (Dormand-Prince), and
// every method of the study run on it, each run's frames measured against the reference's beside the size of the
// motion (curtain_runs.hpp).
#include "curtain_runs.hpp"

#include "analysis/lattice_frequency.hpp"
#include "program/interrupt.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace cloth;

namespace ch10 {

SceneParams scene_params(const CurtainScene& c, int n) {
  SceneParams p = fabric(n, curtain_K);
  p.pins = c.pins;
  p.initial_swing = c.swing;
  return p;
}

std::string scene_flags(const CurtainScene& c, int n) {
  const SceneParams p = scene_params(c, n);
  return format("--grid %dx%d --spacing %.4g --mass %.4g --K %g --damping %g --v0 0 --pins %s%s --t-end %g", n, n,
                p.grid.d, p.mass, curtain_K, p.damping, pin_set_name(p.pins),
                c.swing != 0 ? format(" --swing %g", c.swing).c_str() : "", c.T);
}

namespace {

double explicit_step(const std::string& key, const SceneParams& p) {
  const double reach = key == "rk4" ? 2 * std::sqrt(2.0) : 2.0;  // on the imaginary axis (Chapter 7)
  return 0.95 * reach / lattice_fastest_frequency({curtain_K, curtain_K, curtain_K, p.mass});
}

// [curtain_run]
/// Runs `key` at step h (frame_interval / h or h / frame_interval whole) to T, keeping the state at every frame it
/// lands on; the stepping alone is timed. A failed step or a diverging state ends the run: a result, kept with
/// where it stopped.
CurtainRun run_method(const Scene& scene, const std::string& key, double h, double T, const SceneResult& ref) {
  ForceField field(scene);
  auto stepper = make_method(key, field);
  CurtainRun run;
  run.method = key;
  run.h = h;
  run.steps = std::llround(T / h);
  const long long every = std::max(1LL, std::llround(1 / (frame_rate * h)));  // steps between recorded frames
  std::vector<Vector> xs{scene.initial_positions()}, vs{scene.initial_velocities()};
  Vector x = xs[0], v = vs[0];
  const double start = thread_cpu_seconds();
  for (long long k = 1; k <= run.steps; ++k) {
    throw_if_interrupted();
    if (!stepper->step(h, x, v)) {
      run.ok = false;
      run.message = format("step %lld (t = %.4g s) failed: %s", k, static_cast<double>(k) * h,
                           stepper->failure().reason.c_str());
      break;
    }
    if (!x.allFinite() || x.cwiseAbs().maxCoeff() > 100) {
      run.ok = false;
      run.message = format("diverged at step %lld (t = %.4g s)", k, static_cast<double>(k) * h);
      break;
    }
    if (k % every == 0) xs.push_back(x), vs.push_back(v);
  }
  run.seconds = thread_cpu_seconds() - start;
  std::vector<Frame> frames;
  for (std::size_t f = 0; f < xs.size(); ++f) {
    frames.push_back({static_cast<double>(f) * static_cast<double>(every) * h, Vector(3 * scene.particle_count())});
    scene.all_positions(xs[f], frames.back().positions);
    run.t.push_back(frames.back().t);
  }
  run.edge = free_edge_height(scene.grid(), frames);
  run.strain = largest_strain(scene, frames);
  if (!run.ok) return run;
  run.error = trajectory_error(frames, ref.reference.frames);
  run.energy_lost = energy_lost(field.energy(x, v), ref.reference.energy.back(), ref.peak_kinetic).fraction;
  run.minimum = first_minimum_time(run.t, run.edge);
  return run;
}
// [curtain_run]

}  // namespace

SceneResult measure_scene(const CurtainScene& c, int n, bool quick) {
  SceneResult r;
  r.scene = c;
  r.n = n;
  const Scene scene(scene_params(c, n));
  ForceField field(scene);
  const int frames = static_cast<int>(std::lround(c.T * frame_rate));
  const double tolerance = quick ? 1e-8 : 1e-10;
  const double start = thread_cpu_seconds();
  r.reference = reference_trajectory(field, scene.initial_positions(), scene.initial_velocities(), c.T, frames,
                                     tolerance, &interrupt_flag());
  throw_if_interrupted();
  std::printf("%s %dx%d: reference dopri5 at %g, %lld steps, %.2f s\n", c.tag.c_str(), n, n, tolerance,
              r.reference.steps, thread_cpu_seconds() - start);
  if (!quick && n == 20) {
    r.check_tolerance = 1e-12;
    const ReferenceTrajectory tight = reference_trajectory(field, scene.initial_positions(), scene.initial_velocities(),
                                                           c.T, frames, r.check_tolerance, &interrupt_flag());
    throw_if_interrupted();
    r.check = trajectory_error(r.reference.frames, tight.frames).over_frames;
    std::printf("  against dopri5 at %g: %.2g m\n", r.check_tolerance, r.check);
  }
  r.motion = motion_size(r.reference.frames);
  for (const Energy& e : r.reference.energy) r.peak_kinetic = std::max(r.peak_kinetic, e.kinetic);
  r.reference_strain = largest_strain(scene, r.reference.frames);
  for (const Frame& f : r.reference.frames) r.t.push_back(f.t);
  r.edge = free_edge_height(scene.grid(), r.reference.frames);
  r.reference_minimum = first_minimum_time(r.t, r.edge);
  for (const MethodRow& m : curtain_methods) {
    std::vector<double> steps = m.steps;
    if (quick && steps.size() > m.quick_steps) steps.resize(m.quick_steps);
    if (steps.empty()) {  // a whole number of steps per frame, each below 95 % of the stable step
      const double per_frame = std::ceil(1 / (frame_rate * explicit_step(m.key, scene.params())));
      steps = {1 / (frame_rate * per_frame)};
    }
    for (double h : steps) {
      r.runs.push_back(run_method(scene, m.key, h, c.T, r));
      const CurtainRun& run = r.runs.back();
      std::printf("  %-18s h %-9.3g %7.3f s  error at T %.3g, over frames %.3g %s\n", m.key.c_str(), h, run.seconds,
                  run.error.at_end, run.error.over_frames, run.message.c_str());
    }
  }
  return r;
}

}  // namespace ch10
