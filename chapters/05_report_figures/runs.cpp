// The chapter's runs, spread over threads, and what a run's energy and sag say (see experiments.hpp).
#include "experiments.hpp"

#include "integrators/method_registry.hpp"
#include "program/parallel_runs.hpp"
#include "program/run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

namespace ch05 {

using namespace cloth;

std::vector<Run> run_all(const Options& opt, const Settings& settings) {
  const double h = opt.run.dt, T = opt.run.t_end;
  std::vector<Run> runs;
  for (const std::string& m : methods)
    for (const ReportCase& c : report_cases) runs.push_back({m, c.K, c.D, T, true, {}});
  if (settings.sweep)
    for (const std::string& m : methods)
      for (const double K : sweep_K)
        for (const double D : sweep_D)
          runs.push_back({m, K, D, m == "implicit_euler" ? settings.sweep_t_end_implicit : T, false, {}});

  // Implicit Euler first, as it is the slowest, so that the threads finish together.
  std::vector<std::size_t> order(runs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return (runs[a].method == "implicit_euler") > (runs[b].method == "implicit_euler");
  });
  const auto steps_of = [&](double t_end) { return static_cast<int>(std::ceil(t_end / h * (1 - 1e-12))); };
  const double wall = run_in_parallel(order.size(), settings.threads, [&](std::size_t job) {
    Run& run = runs[order[job]];
    const Scene scene(with_K_and_D(opt.scene, run.K, run.D));
    ForceField field(scene);
    auto stepper = make_stepper(run.method, field);
    RunSettings s = opt.run;
    s.t_end = run.t_end;
    s.frames = run.figure ? steps_of(run.t_end) : 1;  // the figures' runs keep the cloth at every step (sag)
    run.result = simulate(*stepper, s);
    if (run.figure) {  // the model page's outputs, frames.dat thinned to movie_frames + 1 frames
      RunResult thin = run.result;
      thin.frames.clear();
      // At least 1: a run with fewer steps than movie frames keeps every frame (a stride of 0 would never end).
      const int stride = std::max(1, s.frames / movie_frames);
      for (std::size_t k = 0; k < run.result.frames.size(); k += static_cast<std::size_t>(stride))
        thin.frames.push_back(run.result.frames[k]);
      s.out_dir = opt.run.out_dir + "/runs/" + run_name(run);
      prepare_output_dir(s.out_dir);
      write_outputs(thin, *stepper, s);
    }
  });
  std::printf("%zu runs in %.1f s on %d threads\n", runs.size(), wall, settings.threads);
  return runs;
}

const Run& sweep_run(const std::vector<Run>& runs, std::size_t m, std::size_t k, std::size_t d) {
  const std::size_t first = methods.size() * report_cases.size();
  return runs[first + (m * sweep_K.size() + k) * sweep_D.size() + d];
}

std::string run_name(const Run& run) { return run.method + "_" + ReportCase{run.K, run.D}.name(); }

// [energy_measures]
// What the figures and tables say of a run's energy, relative to E(0) (the launch's kinetic energy, 79.2 kJ):
//   gain  = max over s <= t of (E(t) - E(s)) / |E(0)|, the largest rise of the energy over any stretch of the run,
//           >= 0. The exact solution's energy never rises (it is constant for D = 0 and falls for D > 0), so any
//           rise is the method's error, also one that starts after the dampers took the energy below E(0).
//   final = (E(T) - E(0)) / |E(0)|: negative when energy was lost, by the dampers or by the method.
//   peak  = max over t of E(t) / E(0).
EnergyMeasures energy_measures(const std::vector<EnergySample>& energy) {
  EnergyMeasures m;
  const double e0 = energy.front().energy.total();
  double lowest_so_far = e0;
  for (const EnergySample& s : energy) {
    const double e = s.energy.total();
    lowest_so_far = std::min(lowest_so_far, e);
    m.gain = std::max(m.gain, (e - lowest_so_far) / std::abs(e0));
    m.peak = std::max(m.peak, e / e0);
  }
  m.final_change = (energy.back().energy.total() - e0) / std::abs(e0);
  return m;
}
// [energy_measures]

// Pinned corners are left out: a cloth that rebounds above its pins would otherwise read as z = 0.
double lowest_z(const Scene& scene, const Vector& positions) {
  double z = std::numeric_limits<double>::infinity();
  for (int p = 0; p < scene.particle_count(); ++p)
    if (!scene.is_pinned(p)) z = std::min(z, positions[3 * p + 2]);
  return z;
}

std::string outcome(const RunResult& r) {
  switch (r.status) {
    case RunStatus::ok: return "bounded";
    case RunStatus::diverged: return "diverged";
    case RunStatus::interrupted: return "interrupted";
    case RunStatus::step_failed: break;
  }
  // A failed step is a failure of the solver, not of stability: say which ("newton not converged").
  std::string kind = step_failure_name(r.failure);
  std::replace(kind.begin(), kind.end(), '_', ' ');
  return kind;
}

double stop_time(const RunResult& r, double h) { return r.status != RunStatus::ok ? r.t + h : std::nan(""); }

}  // namespace ch05
