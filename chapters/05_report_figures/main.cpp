// Chapter 5: the report's comparison regenerated. Runs explicit Euler, symplectic Euler, RK4 and implicit Euler on
// the report scene at (K, D) = (50, 0), (200, 0), (200, 20), then sweeps K x D per method, and writes the data
// of the chapter's figures (strain-coloured meshes, energy, sag, animations, heat maps) and their summary tables.
#include "program/command_line.hpp"
#include "analysis/fastest_modes.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/methods.hpp"
#include "integrators/simulate.hpp"
#include "program/run_outputs.hpp"
#include "run_pool.hpp"
#include "strain_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace cloth;
using namespace cloth::ch05;

namespace {

const std::vector<std::string> methods = {"explicit_euler", "symplectic_euler", "rk4", "implicit_euler"};
const std::vector<std::string> method_titles = {"explicit Euler", "symplectic Euler", "RK4", "implicit Euler"};

// [report_grid]
// The report's three configurations and its six figures (Figures 2 to 7), with its own captions.
struct Config {
  double K, D;
};
const std::vector<Config> configs = {{50, 0}, {200, 0}, {200, 20}};

struct ReportFigure {
  int number;
  std::string method;
  int config;  // index into configs
  std::string caption_method;
};
const std::vector<ReportFigure> report_figures = {
    {2, "explicit_euler", 1, "Euler's method"},           {3, "explicit_euler", 0, "Explicit Euler's method"},
    {4, "explicit_euler", 2, "Explicit Euler's method"},  {5, "rk4", 1, "Runge-Kutta's method"},
    {6, "rk4", 2, "Runge-Kutta's method"},                {7, "implicit_euler", 0, "Implicit Euler's method"}};

// The sweep: every K against every D, per method.
const std::vector<double> sweep_K = {10, 25, 50, 100, 200, 500, 1000};
const std::vector<double> sweep_D = {0, 1, 5, 20};
// [report_grid]

// The instants of the sheets, as fractions of T (t = 0.1, 0.5, 1, 2 s for T = 2 s), and how many animation frames.
const std::vector<double> sheet_fractions = {0.05, 0.25, 0.5, 1.0};
constexpr int movie_frames = 20;

std::string run_name(const std::string& method, double K, double D) {
  return method + "_K" + format_number(K) + "_D" + format_number(D);
}

// [energy_measures]
// What the figures and tables say of a run's energy, relative to E(0) (the launch's kinetic energy, 79.2 kJ):
//   gain  = max over t of (E(t) - E(0)) / |E(0)|, >= 0 since t = 0 is included. The exact solution never gains
//           energy (it conserves it for D = 0 and dissipates it for D > 0), so any gain is the method's error.
//   final = (E(T) - E(0)) / |E(0)|: negative when energy was lost, by the dampers or by the method.
struct EnergyMeasures {
  double gain = 0, final_change = 0;
};
EnergyMeasures energy_measures(const std::vector<EnergySample>& energy) {
  EnergyMeasures m;
  const double e0 = energy.front().energy.total();
  for (const EnergySample& s : energy) m.gain = std::max(m.gain, (s.energy.total() - e0) / std::abs(e0));
  m.final_change = (energy.back().energy.total() - e0) / std::abs(e0);
  return m;
}
// [energy_measures]

// The lowest free particle (positions of every particle in grid order). Pinned corners are left out: a cloth
// that rebounds above its pins would otherwise read as z = 0.
double lowest_z(const Scene& scene, const Vector& positions) {
  double z = std::numeric_limits<double>::infinity();
  for (int p = 0; p < scene.particle_count(); ++p)
    if (!scene.is_pinned(p)) z = std::min(z, positions[3 * p + 2]);
  return z;
}

// Builds gnuplot's array initializers: "a, b, c" and "\"text\"".
void add(std::string& list, const std::string& item) {
  if (!list.empty()) list += ", ";
  list += item;
}
std::string quote(const std::string& text) {
  std::string q = "\"";
  q += text;
  q += '"';
  return q;
}

bool diverged(const RunResult& r) { return r.status != RunStatus::ok; }

// One short phrase for figures: a run that left the divergence bound "diverged", one whose Newton iteration
// gave up "Newton failed" (a failure of the solver, not of stability), with the time of the failed step.
std::string outcome(const RunResult& r, double h) {
  char buf[96];
  if (r.status == RunStatus::ok) return "bounded";
  std::snprintf(buf, sizeof buf, "%s at t = %.3g s", r.status == RunStatus::diverged ? "diverged" : "Newton failed",
                r.t + h);
  return buf;
}

// The time at which a run stopped being sane: the step after the last sane one.
double divergence_time(const RunResult& r, double h) { return diverged(r) ? r.t + h : std::nan(""); }

// [stiffness_eigenvalue]
// Largest eigenvalue lambda of -df/dx / (m K) at the rest state. At rest no spring is under tension, so
// -df/dx = K sum u u^T (one 3x3 block per spring) and the highest mode's frequency is omega_max = sqrt(lambda K / m).
// The projected dampers have -df/dv = D sum u u^T, the same matrix with D for K, so the fastest damped mode decays
// at rate lambda D / m. These set the stability limits of Chapters 2-4 for each (K, D).
double rest_stiffness_eigenvalue(const SceneParams& base) {
  SceneParams p = base;
  p.stiffness = 1;
  p.damping = 0;
  const Scene scene(p);
  ForceField field(scene);
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  const Vector x = scene.initial_positions();
  field.jacobians(x, Vector::Zero(x.size()), dfdx, dfdv);
  return largest_rate(dfdx, p.mass);  // analysis/fastest_modes.hpp: power iteration on -M^{-1} df/dx
}

// The same damping eigenvalue, lambda_D = largest eigenvalue of sum u u^T / m, on a deformed cloth (every particle's
// positions in grid order): u now points wherever the springs point, so lambda_D moves away from its rest value.
double damping_eigenvalue(const SceneParams& base, const Vector& positions) {
  SceneParams p = base;
  p.stiffness = 1;  // any K > 0: df/dv of the projected dampers does not depend on it
  p.damping = 1;
  const Scene scene(p);
  ForceField field(scene);
  Vector x(scene.dof_count());
  for (int s = 0; s < scene.free_count(); ++s) x.segment<3>(3 * s) = positions.segment<3>(3 * scene.particle_of_slot(s));
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, Vector::Zero(x.size()), dfdx, dfdv);
  return largest_rate(dfdv, p.mass);
}
// [stiffness_eigenvalue]

struct Run {
  std::string method;
  double K = 0, D = 0;
  double t_end = 0;
  bool main = false;  // one of the twelve runs of the figures (frames every step) or a sweep run
  RunResult result;
};

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch05_report_figures",
                  "Chapter 5: the report's comparison. Runs explicit Euler, symplectic Euler, RK4 and implicit Euler\n"
                  "at (K, D) = (50, 0), (200, 0), (200, 20), and sweeps K in {10..1000} x D in {0, 1, 5, 20}.\n"
                  "--K and --damping are ignored: the chapter sets them. Figure data go to --out.");
  int threads = 2;
  double sweep_t_end_implicit = 0;  // 0: the same T as every other run
  bool sweep = true;
  cli.add_value("--threads", "n", "runs in parallel, 1..64 [2]", [&](const std::string& s) {
    const long long n = parse_integer(s);
    if (n < 1 || n > 64) throw InputError("expected an integer from 1 to 64, got '" + s + "'");
    threads = static_cast<int>(n);
  });
  cli.add_value("--sweep-t-end-implicit", "T", "simulated time of implicit Euler's sweep runs [s] [same as --t-end]",
                [&](const std::string& s) {
                  sweep_t_end_implicit = parse_number(s);
                  if (sweep_t_end_implicit <= 0) throw InputError("expected a positive time, got '" + s + "'");
                });
  cli.add_switch("--no-sweep", "skip the K x D sweep", [&] { sweep = false; });

  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const double h = opt.run.dt, T = opt.run.t_end;
    if (sweep_t_end_implicit > T) throw InputError("--sweep-t-end-implicit: must not exceed --t-end");
    if (sweep_t_end_implicit == 0) sweep_t_end_implicit = T;
    const std::string dir = opt.run.out_dir + "/";
    prepare_output_dir(opt.run.out_dir);

    // The jobs: the twelve runs of the figures, then the sweep; implicit Euler first, as it is the slowest.
    std::vector<Run> runs;
    for (const std::string& m : methods)
      for (const Config& c : configs) runs.push_back({m, c.K, c.D, T, true, {}});
    if (sweep)
      for (const std::string& m : methods)
        for (double K : sweep_K)
          for (double D : sweep_D) runs.push_back({m, K, D, m == "implicit_euler" ? sweep_t_end_implicit : T, false, {}});
    std::vector<std::size_t> order(runs.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return (runs[a].method == "implicit_euler") > (runs[b].method == "implicit_euler");
    });

    const auto steps_of = [&](double t_end) { return static_cast<int>(std::ceil(t_end / h * (1 - 1e-12))); };
    const double wall = run_in_parallel(order.size(), threads, [&](std::size_t job) {
      Run& run = runs[order[job]];
      SceneParams p = opt.scene;
      p.stiffness = run.K;
      p.damping = run.D;
      const Scene scene(p);
      ForceField field(scene);
      auto stepper = make_stepper(run.method, field);
      RunSettings s = opt.run;
      s.t_end = run.t_end;
      s.frames = run.main ? steps_of(run.t_end) : 1;  // the figures' runs keep the cloth at every step (sag)
      run.result = simulate(*stepper, s);
      if (run.main) {  // docs/model.md's outputs, frames.dat thinned to movie_frames + 1 frames
        RunResult thin = run.result;
        thin.frames.clear();
        const int stride = s.frames / movie_frames;
        for (std::size_t k = 0; k < run.result.frames.size(); k += static_cast<std::size_t>(stride))
          thin.frames.push_back(run.result.frames[k]);
        s.out_dir = dir + "runs/" + run_name(run.method, run.K, run.D);
        prepare_output_dir(s.out_dir);
        write_outputs(thin, *stepper, s);
      }
    });
    std::printf("%zu runs in %.1f s on %d threads\n", runs.size(), wall, threads);

    // ---- the twelve runs of the figures ----
    const SceneParams& sp = opt.scene;
    const Scene base_scene(sp);  // K and D aside, every run's scene: which particles are pinned, the springs
    std::FILE* summary = std::fopen((dir + "summary.dat").c_str(), "w");
    std::fprintf(summary,
                 "# method K D status t_diverged[s] energy_gain energy_final_change sag_T[m] min_z_run[m] "
                 "max_strain_T newton_per_step wall[s]\n"
                 "# energy_gain = max_t (E(t)-E(0))/|E(0)|, energy_final_change = (E(T)-E(0))/|E(0)|, over the "
                 "sane part of a diverged run; sag_T = lowest z of the last sane state\n");
    std::printf("\n%-17s %5s %4s  %-9s %8s %11s %11s %8s %8s %10s\n", "method", "K", "D", "status", "t_div",
                "E gain", "E(T)/E0-1", "sag_T", "min z", "max strain");
    // gnuplot reads the figures' bookkeeping from runs.gp: which block of each mesh file to draw, and the labels.
    std::string gp_names, gp_titles, gp_status, gp_reached, gp_box, gp_blocks, gp_labels, gp_instants, gp_logscale, gp_sag_low;
    for (std::size_t r = 0; r < methods.size() * configs.size(); ++r) {
      const Run& run = runs[r];
      const RunResult& res = run.result;
      const std::string name = run_name(run.method, run.K, run.D);
      const Scene scene([&] {
        SceneParams p = sp;
        p.stiffness = run.K;
        p.damping = run.D;
        return p;
      }());
      Vector last(3 * scene.particle_count());
      scene.all_positions(res.x, last);
      const EnergyMeasures e = energy_measures(res.energy);
      double min_z = 0;
      for (const Frame& f : res.frames) min_z = std::min(min_z, lowest_z(scene, f.positions));
      const double t_div = divergence_time(res, h);
      const std::string status = res.status == RunStatus::ok         ? "ok"
                                 : res.status == RunStatus::diverged ? "diverged"
                                                                     : "newton_failed";
      std::fprintf(summary, "%s %g %g %s %.4g %.6g %.6g %.6g %.6g %.4g %.3g %.3f\n", run.method.c_str(), run.K, run.D,
                   status.c_str(), t_div, e.gain, e.final_change, lowest_z(scene, last), min_z,
                   max_abs_strain(scene, last),
                   res.steps ? static_cast<double>(res.counters.newton_iterations) / static_cast<double>(res.steps) : 0.0,
                   res.wall_seconds);
      std::printf("%-17s %5g %4g  %-9s %8.4g %11.4g %11.4g %8.4g %8.4g %10.4g\n", run.method.c_str(), run.K, run.D,
                  status.c_str(), t_div, e.gain, e.final_change, lowest_z(scene, last), min_z, max_abs_strain(scene, last));

      // Energy and sag against time, one line per step.
      std::FILE* series = std::fopen((dir + "series_" + name + ".dat").c_str(), "w");
      std::fprintf(series, "# %s K=%g D=%g: t[s] E_total[J] E/E(0) lowest_z[m]\n", run.method.c_str(), run.K, run.D);
      const double e0 = res.energy.front().energy.total();
      for (std::size_t k = 0; k < res.energy.size() && k < res.frames.size(); ++k)
        std::fprintf(series, "%.6g %.10g %.10g %.8g\n", res.energy[k].t, res.energy[k].energy.total(),
                     res.energy[k].energy.total() / e0, lowest_z(scene, res.frames[k].positions));
      std::fclose(series);

      // The strain-coloured structural mesh every T / movie_frames, then the last sane state if the run diverged.
      std::FILE* mesh = std::fopen((dir + "mesh_" + name + ".dat").c_str(), "w");
      const std::size_t stride = static_cast<std::size_t>(steps_of(T) / movie_frames);
      int blocks = 0;
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(0.0), hi = lo;  // the animation's fixed box
      const auto draw = [&](const Vector& positions, double t) {
        write_strain_block(mesh, scene, positions, t, SpringFamily::structural);
        for (Eigen::Index k = 0; k < positions.size(); k += 3) {
          lo = lo.cwiseMin(positions.segment<3>(k));
          hi = hi.cwiseMax(positions.segment<3>(k));
        }
        ++blocks;
      };
      for (std::size_t k = 0; k < res.frames.size(); k += stride) draw(res.frames[k].positions, res.frames[k].t);
      if (diverged(res)) draw(last, res.t);
      std::fclose(mesh);
      for (int a = 0; a < 3; ++a) add(gp_box, format_number(lo[a], 4) + ", " + format_number(hi[a], 4));

      add(gp_names, quote(name));
      add(gp_titles, quote(method_titles[r / configs.size()]));
      add(gp_status, quote(diverged(res) ? outcome(res, h) : "bounded, max E/E(0) = " + format_number(1 + e.gain, 3)));
      add(gp_reached, format_number(res.t, 4));
      add(gp_blocks, std::to_string(blocks));
      for (double frac : sheet_fractions) {
        const int wanted = static_cast<int>(std::lround(frac * movie_frames));
        const bool have = static_cast<std::size_t>(wanted) * stride < res.frames.size();
        add(gp_instants, std::to_string(have ? wanted : blocks - 1));
        add(gp_labels, quote(have ? "t = " + format_number(frac * T) + " s"
                                  : "t = " + format_number(frac * T) + " s: " + outcome(res, h) +
                                        ", last frame t = " + format_number(res.t, 3) + " s"));
      }
    }
    std::fclose(summary);
    // Per configuration: a log energy axis when some method's energy grew tenfold, and a sag range that shows
    // the bounded runs (exploding ones leave it, which the plot says).
    for (std::size_t c = 0; c < configs.size(); ++c) {
      double worst_gain = 0, low = 0;
      for (std::size_t m = 0; m < methods.size(); ++m) {
        const Run& run = runs[m * configs.size() + c];
        worst_gain = std::max(worst_gain, energy_measures(run.result.energy).gain);
        if (!diverged(run.result) && energy_measures(run.result.energy).gain < 1.0)
          for (const Frame& f : run.result.frames) low = std::min(low, lowest_z(base_scene, f.positions));
      }
      add(gp_logscale, worst_gain > 9.0 ? "1" : "0");
      add(gp_sag_low, format_number(1.15 * low, 3));
    }

    std::FILE* gp = std::fopen((dir + "runs.gp").c_str(), "w");
    const auto n = [](std::size_t k) { return std::to_string(k); };
    const std::size_t nr = methods.size() * configs.size();
    std::fprintf(gp, "# Written by ch05_report_figures: the bookkeeping of plot.gp. Run r = m*%zu + c + 1.\n",
                 configs.size());
    std::fprintf(gp, "h = %g\nt_end = %g\nnmethods = %zu\nnconfigs = %zu\nninstants = %zu\n", h, T, methods.size(),
                 configs.size(), sheet_fractions.size());
    std::string ks, ds;
    for (std::size_t c = 0; c < configs.size(); ++c)
      add(ks, format_number(configs[c].K)), add(ds, format_number(configs[c].D));
    std::fprintf(gp, "array cfg_K[%zu] = [%s]\narray cfg_D[%zu] = [%s]\n", configs.size(), ks.c_str(), configs.size(),
                 ds.c_str());
    std::fprintf(gp, "array run_name[%s] = [%s]\narray run_method[%s] = [%s]\narray run_status[%s] = [%s]\n",
                 n(nr).c_str(), gp_names.c_str(), n(nr).c_str(), gp_titles.c_str(), n(nr).c_str(), gp_status.c_str());
    std::fprintf(gp, "array run_blocks[%s] = [%s]\narray run_t_reached[%s] = [%s]\n", n(nr).c_str(), gp_blocks.c_str(),
                 n(nr).c_str(), gp_reached.c_str());
    std::fprintf(gp, "array run_box[%s] = [%s]  # xmin, xmax, ymin, ymax, zmin, zmax per run\n",
                 n(6 * nr).c_str(), gp_box.c_str());
    std::fprintf(gp, "array instant_block[%s] = [%s]\narray instant_label[%s] = [%s]\n",
                 n(nr * sheet_fractions.size()).c_str(), gp_instants.c_str(), n(nr * sheet_fractions.size()).c_str(),
                 gp_labels.c_str());
    std::fprintf(gp, "array cfg_logscale[%zu] = [%s]\narray cfg_sag_low[%zu] = [%s]\n", configs.size(),
                 gp_logscale.c_str(), configs.size(), gp_sag_low.c_str());
    std::string fig_runs, fig_captions, fig_numbers;
    for (std::size_t f = 0; f < report_figures.size(); ++f) {
      const ReportFigure& rf = report_figures[f];
      const std::size_t m = static_cast<std::size_t>(std::find(methods.begin(), methods.end(), rf.method) - methods.begin());
      const Config& c = configs[static_cast<std::size_t>(rf.config)];
      add(fig_runs, n(m * configs.size() + static_cast<std::size_t>(rf.config) + 1));
      add(fig_numbers, std::to_string(rf.number));
      add(fig_captions, quote("Figure " + std::to_string(rf.number) + ": " + rf.caption_method + " with K=" +
                              format_number(c.K) + " and D=" + format_number(c.D)));
    }
    std::fprintf(gp, "array fig_run[%zu] = [%s]\narray fig_number[%zu] = [%s]\narray fig_caption[%zu] = [%s]\n",
                 report_figures.size(), fig_runs.c_str(), report_figures.size(), fig_numbers.c_str(),
                 report_figures.size(), fig_captions.c_str());
    std::fprintf(gp, "sweep_t_end_implicit = %g\n", sweep_t_end_implicit);
    std::fclose(gp);

    // ---- theory: the stability numbers of Chapters 2-4 for each configuration ----
    const double lambda = rest_stiffness_eigenvalue(sp);
    std::FILE* theory = std::fopen((dir + "theory.txt").c_str(), "w");
    std::fprintf(theory, "lambda_max = %.6g  # of -df/dx / (m K) at rest: omega_max = sqrt(lambda K / m)\n", lambda);
    std::printf("\nrest-state stiffness eigenvalue lambda_max = %.4g (omega_max = sqrt(lambda K / m))\n", lambda);
    std::printf("%5s %4s %10s %9s %15s %15s %12s\n", "K", "D", "omega_max", "h omega", "EE factor/step",
                "factor^(T/h)", "h lambda D/m");
    for (double K : sweep_K)
      for (double D : sweep_D) {
        const double omega = std::sqrt(lambda * K / sp.mass), ho = h * omega;
        const double rate = h * lambda * D / sp.mass;
        std::fprintf(theory,
                     "K = %g D = %g omega_max = %.4g h_omega = %.4g explicit_euler_energy_factor_per_step = %.4g "
                     "over_T = %.4g h_lambda_D_over_m = %.4g\n",
                     K, D, omega, ho, 1 + ho * ho, std::pow(1 + ho * ho, T / h), rate);
        if (D == 0 || K == 200)
          std::printf("%5g %4g %10.4g %9.4g %15.4g %15.4g %12.4g\n", K, D, omega, ho, 1 + ho * ho,
                      std::pow(1 + ho * ho, T / h), rate);
      }
    // The damped runs' fastest damped mode on the cloth as it deforms: h lambda_D D / m against the real-axis
    // stability limits, 2 for explicit Euler and 2.785 for RK4 (Chapter 3).
    for (std::size_t r = 0; r < nr; ++r) {
      const Run& run = runs[r];
      if (run.D == 0 || run.method != "implicit_euler") continue;
      for (std::size_t k = 0; k < run.result.frames.size(); k += run.result.frames.size() / 4) {
        const Frame& f = run.result.frames[k];
        const double lambda_d = damping_eigenvalue(sp, f.positions);
        std::fprintf(theory, "deformed_damping K = %g D = %g t = %g lambda_D = %.4g h_lambda_D_D_over_m = %.4g\n", run.K,
                     run.D, f.t, lambda_d, h * lambda_d * run.D / sp.mass);
        std::printf("implicit Euler K = %g, D = %g, t = %4.2f s: lambda_D = %.4g, h lambda_D D / m = %.4g\n", run.K,
                    run.D, f.t, lambda_d, h * lambda_d * run.D / sp.mass);
      }
    }
    std::fclose(theory);

    // ---- the sweep ----
    if (sweep) {
      std::FILE* out = std::fopen((dir + "sweep.dat").c_str(), "w");
      std::fprintf(out,
                   "# method_index(0 explicit_euler,1 symplectic_euler,2 rk4,3 implicit_euler) K_index D_index K D "
                   "status(0 bounded,1 diverged,2 Newton failed) t_stopped[s] energy_gain energy_final_change sag_T[m] t_end[s] newton_per_step\n"
                   "# energy_gain = max_t (E(t)-E(0))/|E(0)| (>= 0; 0 for a method that never adds energy), "
                   "energy_final_change = (E(T)-E(0))/|E(0)|; NaN for a diverged run\n");
      std::size_t r = nr;
      for (std::size_t m = 0; m < methods.size(); ++m) {
        for (std::size_t ki = 0; ki < sweep_K.size(); ++ki)
          for (std::size_t di = 0; di < sweep_D.size(); ++di, ++r) {
            const Run& run = runs[r];
            const RunResult& res = run.result;
            const bool div = diverged(res);
            const EnergyMeasures e = energy_measures(res.energy);
            const double nan = std::nan("");
            std::fprintf(out, "%zu %zu %zu %g %g %d %.4g %.6g %.6g %.6g %g %.3g\n", m, ki, di, run.K, run.D,
                         static_cast<int>(res.status),
                         divergence_time(res, h), div ? nan : e.gain, div ? nan : e.final_change,
                         div ? nan : lowest_z(base_scene, res.frames.back().positions), run.t_end,
                         res.steps ? static_cast<double>(res.counters.newton_iterations) / static_cast<double>(res.steps)
                                   : 0.0);
          }
        std::fprintf(out, "\n\n");
      }
      std::fclose(out);
    }
    return 0;
  });
}
