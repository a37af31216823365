// The chapter's runs, spread over threads, and what a run's energy and sag say (see experiments.hpp).
#include "experiments.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "program/interrupt.hpp"
#include "program/limits.hpp"
#include "program/output_kinds.hpp"
#include "program/parallel_runs.hpp"
#include "program/run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

namespace ch05 {

using namespace cloth;

OutputList outputs(bool sweep) {
  using namespace cloth::output_kinds;
  OutputList files = {
      {"parameters.dat", figure, "h, T and the numbers of methods and cases, for the figures' loops"},
      {"runs.dat", figure, "each figure run's name, method, status and the extent of its meshes"},
      {"instants.dat", figure, "the instants of the strain-coloured sheets"},
      {"cases.dat", figure, "each case's K, D and axes"},
      {"figures.dat", figure, "the report's figures: which run each shows"},
      {"summary.dat", data, "each figure run's energy gain, sag and outcome"},
      {"summary.md", fragment, "the same, as the page's table"},
      {"theory.txt", data, "the stiffness and damping eigenvalues the page quotes"},
      {"theory.md", fragment, "those eigenvalues, as the page's table"},
      {"deformed_damping.md", fragment, "the damping rate on the deformed cloth"},
      {"growth.md", fragment, "when and by how much RK4's energy rises"}};
  if (sweep)
    files = files + OutputList{{"sweep.dat", figure, "energy gain and outcome over K x D, per method"},
                               {"sweep.md", fragment, "the sweep's summary"},
                               {"sweep_implicit.md", fragment, "implicit Euler's sweep to its shorter T"}};
  for (const std::string& m : methods)
    for (const ReportCase& c : report_cases) {
      const std::string name = run_name({m, c.K, c.D, 0, true, {}});
      files.push_back({"series_" + name + ".dat", figure, "energy and sag against time"});
      files.push_back({"mesh_" + name + ".dat", figure, "strain-coloured sheets at the instants"});
      files = files + run_output_specs("runs/" + name);
    }
  return files;
}

void require_memory_of_runs(const Options& opt, const Settings& settings) {
  const double particles = static_cast<double>(opt.scene.grid.M) * opt.scene.grid.N;
  const auto samples = [&](double t_end) {
    RunSettings s = opt.run;
    s.t_end = t_end;
    return static_cast<double>(step_count(s)) + 1;
  };
  const double frame_bytes = 3 * particles * sizeof(double) + sizeof(Frame);
  const double figure_runs = static_cast<double>(methods.size() * report_cases.size());
  // The figures' runs keep the cloth at every step; each run's scene, field and stepper live while it runs.
  double held = figure_runs * samples(opt.run.t_end) * (sizeof(EnergySample) + frame_bytes);
  if (settings.sweep)
    for (const std::string& m : methods)
      held += static_cast<double>(sweep_K.size() * sweep_D.size()) *
              (samples(m == "implicit_euler" ? settings.sweep_t_end_implicit : opt.run.t_end) * sizeof(EnergySample) +
               2 * frame_bytes);
  const double working = settings.threads * particles * implicit_bytes_per_particle(static_cast<long long>(particles));
  const std::string grid = std::to_string(opt.scene.grid.M) + "x" + std::to_string(opt.scene.grid.N);
  if (held >= working)
    require_memory(held + working, "--t-end",
                   "keeping the cloth at every step of the figures' runs (" + format_number(samples(opt.run.t_end), 3) +
                       " states of a " + grid + " grid each)" + (settings.sweep ? " and the sweep's energies" : ""),
                   ": expected a shorter --t-end, a larger --dt or a smaller grid");
  else
    require_memory(held + working, "--grid", std::to_string(settings.threads) + " runs at once on a " + grid + " grid",
                   ": expected a smaller grid or fewer --threads");
}

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
    throw_if_interrupted();  // after Ctrl-C no run starts; the one it stopped kept its outputs
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
      s.out_dir = opt.run.out_dir + "/runs/" + run_name(run);  // made by prepare_outputs (output_names)
      write_outputs(thin, *stepper, s);
    }
    throw_if_interrupted();
  });
  std::printf("%zu runs in %.1f s on %d threads\n", runs.size(), wall, settings.threads);
  return runs;
}

const Run& sweep_run(const std::vector<Run>& runs, std::size_t m, std::size_t k, std::size_t d) {
  const std::size_t first = methods.size() * report_cases.size();
  return runs[first + (m * sweep_K.size() + k) * sweep_D.size() + d];
}

std::string run_name(const Run& run) { return run.method + "_" + ReportCase{run.K, run.D}.name(); }

EnergyReference energy_reference(const SceneParams& scene, double e0) {
  if (e0 != 0) return {std::abs(e0), true};
  // A cloth dropped from rest has E(0) = 0 (no speed, z = 0, springs at rest length), and a ratio to it is
  // infinite. The scale is then one the scene sets for every method alike: W L, the potential energy the cloth's
  // weight W loses in falling by its own side L.
  const Scene s(scene);
  const double weight = s.free_count() * scene.mass * scene.gravity;
  const double side = (std::max(scene.grid.M, scene.grid.N) - 1) * scene.grid.d;
  return {weight * side, false};
}

std::string EnergyReference::description() const {
  const std::string value = format_number(joules / 1000, 3) + " kJ";
  return launch ? "E(0) = " + value + ", the launch's kinetic energy"
                : "W L = " + value + ", the potential energy the cloth's weight W loses in falling by its side L "
                  "(the cloth starts at rest: E(0) = 0)";
}

// [energy_measures]
// What the figures and tables say of a run's energy, relative to E_ref (E(0), the launch's kinetic energy):
//   gain  = max over s <= t of (E(t) - E(s)) / E_ref, the largest rise of the energy over any stretch of the run,
//           >= 0. The exact solution's energy never rises (it is constant for D = 0 and falls for D > 0), so any
//           rise is the method's error, also one that starts after the dampers took the energy below E(0).
//   final = (E(T) - E(0)) / E_ref: negative when energy was lost, by the dampers or by the method.
//   peak  = max over t of E(t) / E_ref.
EnergyMeasures energy_measures(const std::vector<EnergySample>& energy, const EnergyReference& reference) {
  EnergyMeasures m;
  const double e0 = energy.front().energy.total(), scale = reference.joules;
  m.peak = e0 / scale;
  double lowest_so_far = e0, lowest_at = energy.front().t;
  for (const EnergySample& s : energy) {
    const double e = s.energy.total();
    if (e < lowest_so_far) {
      lowest_so_far = e;
      lowest_at = s.t;
    }
    if ((e - lowest_so_far) / scale > m.gain) {
      m.gain = (e - lowest_so_far) / scale;
      m.rise_from = lowest_at;
      m.rise_to = s.t;
    }
    m.peak = std::max(m.peak, e / scale);
  }
  m.final_change = (energy.back().energy.total() - e0) / scale;
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
