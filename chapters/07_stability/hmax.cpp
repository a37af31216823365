// Predicted and measured h_max for Chapter 7.
#include "hmax.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "model/report_cases.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/parallel_runs.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>

namespace ch07 {

using cloth::SceneParams;

// [predicted_hmax]
// Predicted h_max: the largest h with growth factor <= 1 for every mode (strict linear stability), and the
// finite-horizon version: the largest h whose worst mode's energy, which grows like growth^(2 T / h), at most
// doubles over T. A method with no strict limit on the imaginary axis (explicit Euler at D = 0) still has one.
Prediction predict(const StabilityModel& model, const std::vector<Mode>& modes, double T, double h_cap) {
  Prediction p;
  p.strict = cloth::stability_limit_along([&](double h) { return growth_factor(model, h, modes) <= 1 + 1e-12; },
                                          h_cap, 200, 40);
  p.horizon = cloth::stability_limit_along(
      [&](double h) { return 2 * T / h * std::log(growth_factor(model, h, modes)) <= std::log(2.0); }, h_cap, 200, 40);
  return p;
}
// [predicted_hmax]

void write_rest_predictions(const std::string& dir, const RestSpectrum& rest, const SweepSettings& sweep, double m) {
  cloth::OutputFile out(dir + "/predicted_rest.dat");
  std::fprintf(out.get(), "# K D method h_strict h_horizon (rest-state spectrum)\n");
  for (double D : sweep.dampings)
    for (const std::string& method : sweep.methods) {
      const StabilityModel model = stability_model(method);
      for (int k = 0; k <= 16; ++k) {
        const double K = std::pow(10.0, 1.0 + k / 4.0);
        const Prediction r = predict(model, rest_modes(rest, K, D, m), sweep.T, 1.0);
        std::fprintf(out.get(), "%g %g %s %.6g %.6g\n", K, D, method.c_str(), r.strict, r.horizon);
      }
      std::fprintf(out.get(), "\n\n");
    }
  out.commit();
}

namespace {

// [bounded_run]
// The measured notion of "stable": simulate() finishes (status ok: no non-finite or runaway state) and the
// energy above the sagged equilibrium never exceeds twice its initial value, E(t) - E_eq <= 2 (E(0) - E_eq)
// for all t <= T. The exact solution has E(t) <= E(0) for every D >= 0, so a run that doubles its excess energy
// is being driven by the integrator, not the physics.
std::string unbounded_reason(const SceneParams& params, const std::string& method, double h, double T, double E_eq) {
  const cloth::Scene scene(params);
  cloth::ForceField field(scene);
  auto stepper = cloth::make_stepper(method, field);
  cloth::RunSettings run;
  run.dt = h;
  run.t_end = T;
  run.frames = 1;
  run.stop = &cloth::interrupt_flag();
  const cloth::RunResult result = cloth::simulate(*stepper, run, true);
  cloth::throw_if_interrupted();  // a run stopped by Ctrl-C measured nothing
  if (result.status != cloth::RunStatus::ok) return result.message;
  const double excess0 = result.energy.front().energy.total() - E_eq;
  for (const cloth::EnergySample& s : result.energy)
    if (s.energy.total() - E_eq > 2 * excess0) return "excess energy doubled at t = " + cloth::format_number(s.t) + " s";
  return {};
}
// [bounded_run]

// One (K, D, method) of the sweep and what was found.
struct Job {
  double K = 0, D = 0;
  std::string method;
  double guess = 0, E_eq = 0;
  double h = 0;       // largest h found bounded (0: none down to the floor)
  double h_fail = 0;  // smallest h found unbounded (0: none up to the ceiling)
  int runs = 0;
  std::string outcome;  // implicit Euler's probes, or why the job was skipped
  bool skipped = false;
  Prediction rest;             // predicted at the rest state
  double sagged_strict = NAN;  // predicted at the sagged equilibrium (nan: n/a)
};

// Brackets the boundary by doubling or halving from the guess, then bisects it geometrically.
// A run that would cost more than the budget is not made: halving then stops at the last h tried, and the job
// says so (bisection never needs one: it runs between two steps already afforded).
void measure(const SceneParams& params, const SweepSettings& sweep, int stages, Job& job) {
  const double unknowns = cloth::Scene(params).dof_count();
  const auto affordable = [&](double h) { return sweep.run_budget <= 0 || sweep.T / h * stages * unknowns <= sweep.run_budget; };
  const auto ok = [&](double h) {
    ++job.runs;
    return unbounded_reason(params, job.method, h, sweep.T, job.E_eq).empty();
  };
  double lo = 0, hi = 0;
  const double h = std::clamp(job.guess, sweep.h_floor, sweep.h_ceiling);
  if (ok(h)) {
    lo = h;
    while (lo < sweep.h_ceiling) {
      const double up = std::min(2 * lo, sweep.h_ceiling);
      if (!ok(up)) {
        hi = up;
        break;
      }
      lo = up;
    }
  } else {
    hi = h;
    while (hi > sweep.h_floor) {
      const double down = std::max(0.5 * hi, sweep.h_floor);
      if (!affordable(down)) {
        job.outcome = "bracket stopped at h = " + cloth::format_number(hi, 3) + " s: a run at " +
                      cloth::format_number(down, 3) + " s costs more than the budget (--budget 0 lifts it)";
        break;
      }
      if (ok(down)) {
        lo = down;
        break;
      }
      hi = down;
    }
  }
  if (lo > 0 && hi > 0)
    for (int k = 0; k < sweep.bisections; ++k) {
      const double mid = std::sqrt(lo * hi);
      (ok(mid) ? lo : hi) = mid;
    }
  job.h = lo;
  job.h_fail = hi;
}

// Implicit Euler is A-stable, so the question is only whether Newton's method converges: probe h = 0.1 (and
// the report's 0.01 when asked, 10 times dearer).
void probe_implicit(const SceneParams& params, const SweepSettings& sweep, Job& job) {
  for (double h : sweep.dense_implicit ? std::vector<double>{0.01, 0.1} : std::vector<double>{0.1}) {
    const std::string why = unbounded_reason(params, job.method, h, sweep.T, job.E_eq);
    ++job.runs;
    job.outcome += (job.outcome.empty() ? "" : "; ") + std::string("h = ") + cloth::format_number(h) + ": " +
                   (why.empty() ? "bounded" : why);
    if (why.empty()) job.h = h;
    else if (job.h_fail == 0) job.h_fail = h;
  }
}

// A job whose one run costs more than the budget (in unknowns times right-hand sides) is not measured: on
// large grids the sweep keeps to the steps that are cheap there.
void skip_over_budget(Job& job, double h, double cost, double budget) {
  if (budget <= 0 || cost <= budget) return;
  job.skipped = true;
  job.outcome = "not measured: a run at h = " + cloth::format_number(h, 3) + " s costs " + cloth::format_number(cost, 3) +
                " unknown-evaluations, above the budget of " + cloth::format_number(budget, 3) + " (--budget 0 lifts it)";
}

// Right-hand-side evaluations per step of an explicit method (its stages).
int stages(const StabilityModel& model) {
  return model.kind == StabilityModel::Kind::polynomial ? static_cast<int>(model.polynomial.size()) - 1 : 1;
}

// One cell of the book's table: "rest / sagged; measured bracket" (see hmax_table.md in hmax_sweep).
std::string table_cell(const Job& job, const SweepSettings& sweep) {
  const auto n = [](double x) { return cloth::format_number(x, 3); };
  // A method unstable on the imaginary axis (explicit Euler, Heun) has strict limit 0 on an undamped cloth: what
  // the search returns there is set by the tolerance of |R| <= 1 + 1e-12, not by the method.
  const Mode imaginary = {Complex(0, 0.01), Complex(0, -0.01)};
  const bool no_strict_limit =
      job.D == 0 && growth_factor(stability_model(job.method), 1.0, {imaginary}) > 1 + 1e-12;
  std::string predicted = no_strict_limit ? "0 (" + n(sweep.T) + "-s doubling: " + n(job.rest.horizon) + ")"
                                          : n(job.rest.strict) + " / " +
                                                (std::isnan(job.sagged_strict) ? "n/a" : n(job.sagged_strict));
  std::string measured;
  if (job.skipped) measured = "not measured (budget)";
  else if (job.h > 0 && job.h_fail > 0) measured = "[" + n(job.h) + ", " + n(job.h_fail) + "]";
  else if (job.h > 0) measured = ">= " + n(job.h) + " (ceiling)";
  else if (job.h_fail > sweep.h_floor) measured = "below " + n(job.h_fail) + " (budget)";
  else measured = "below " + n(sweep.h_floor);
  return predicted + "; " + measured;
}

// hmax_table.md: predicted against measured h_max for each explicit method and D, at the smallest, the middle and
// the largest K of the sweep (10, 1000 and 1e5 by default).
void write_hmax_table(const std::string& path, const std::vector<Job>& jobs, const SweepSettings& sweep,
                      const std::string& command) {
  const std::vector<double>& Ks = sweep.stiffnesses;
  const std::vector<double> columns = {Ks.front(), Ks[Ks.size() / 2], Ks.back()};
  std::vector<std::string> header = {"method, D"};
  for (double K : columns) header.push_back("K = " + cloth::format_number(K));
  cloth::MarkdownTable table(header);
  std::vector<std::string> methods = {"rk4", "symplectic_euler", "explicit_euler", "heun"};
  for (const std::string& m : sweep.methods)
    if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
  for (double D : sweep.dampings)
    for (const std::string& method : methods) {
      std::vector<std::string> row = {method_label(method) + ", " + cloth::format_number(D)};
      for (double K : columns) {
        const auto job = std::find_if(jobs.begin(), jobs.end(),
                                      [&](const Job& j) { return j.K == K && j.D == D && j.method == method; });
        row.push_back(job == jobs.end() ? "" : table_cell(*job, sweep));
      }
      table.add_row(row);
    }
  cloth::write_table_fragment(path, table, command);
}

}  // namespace

std::vector<std::pair<std::string, std::string>> hmax_sweep(const std::string& dir, const SceneParams& scene,
                                                            const RestSpectrum& rest, Equilibria& equilibria,
                                                            const SweepSettings& sweep, const std::string& command) {
  // The predictions at each (D, K), independent of each other: computed on every thread, written in order.
  struct Cell {
    double K = 0, D = 0;
    std::vector<Job> jobs;
    std::string lines;  // its lines of predicted.dat
  };
  std::vector<Cell> cells;
  for (double D : sweep.dampings)
    for (double K : sweep.stiffnesses) cells.push_back({K, D, {}, {}});
  equilibria.prepare(sweep.stiffnesses, sweep.threads);
  cloth::run_in_parallel(cells.size(), sweep.threads, [&](std::size_t c) {
    cloth::throw_if_interrupted();
    const double K = cells[c].K, D = cells[c].D;
    const cloth::Equilibrium& eq = equilibria.at(K);
    const cloth::Scene s(cloth::with_K_and_D(scene, K, D));
    cloth::ForceField field(s);
    const cloth::Vector zero = cloth::Vector::Zero(eq.x.size());
    const cloth::Energy e = field.energy(eq.x, zero);
    // At the sagged state only the largest eigenvalues are known. A real dominant eigenvalue of an overdamped
    // cloth does not tell symplectic Euler its partner: n/a.
    const std::vector<Complex> largest = largest_eigenvalues(field, eq.x, D, 6);
    const std::vector<Mode> rest_at_K = rest_modes(rest, K, D, scene.mass);
    for (const std::string& method : sweep.methods) {
      const StabilityModel model = stability_model(method);
      const Prediction r = predict(model, rest_at_K, sweep.T, 1.0);
      const std::vector<Mode> sagged = modes_of(largest, model.kind == StabilityModel::Kind::symplectic_euler);
      const double sagged_strict = sagged.empty() ? NAN : predict(model, sagged, sweep.T, 1.0).strict;
      char line[160];
      std::snprintf(line, sizeof line, "%g %g %s %.6g %.6g %.6g\n", K, D, method.c_str(), r.strict, r.horizon, sagged_strict);
      cells[c].lines += line;
      Job job{K, D, method, r.strict > 0 ? r.strict : r.horizon, e.gravity + e.spring, 0, 0, 0, {}, false, r, sagged_strict};
      // A run near the predicted h costs T / h steps of `stages` right-hand sides over every unknown.
      const double h = std::clamp(job.guess, sweep.h_floor, sweep.h_ceiling);
      skip_over_budget(job, h, sweep.T / h * stages(model) * static_cast<double>(eq.x.size()), sweep.run_budget);
      cells[c].jobs.push_back(job);
    }
    // Implicit Euler is A-stable: no predicted limit. It is probed at h = 0.1 s, where it is cheapest; a step
    // there measured hundreds to thousands of right-hand sides' worth (assembly, factorization, Newton
    // iterations on the strongly sagging cloth), counted as 1000.
    if (K == sweep.stiffnesses.front() || K == sweep.stiffnesses.back() || std::abs(std::log10(K) - 3) < 1e-9) {
      Job job{K, D, "implicit_euler", 0.1, e.gravity + e.spring, 0, 0, 0, {}, false, {}, NAN};
      skip_over_budget(job, 0.1, sweep.T / 0.1 * 1000 * static_cast<double>(eq.x.size()), sweep.run_budget);
      cells[c].jobs.push_back(job);
    }
  });
  std::vector<Job> jobs;
  cloth::OutputFile pred(dir + "/predicted.dat");
  std::fprintf(pred.get(), "# K D method h_strict_rest h_horizon_rest h_strict_sagged (largest eigenvalues; nan: n/a)\n");
  for (const Cell& cell : cells) {
    std::fputs(cell.lines.c_str(), pred.get());
    jobs.insert(jobs.end(), cell.jobs.begin(), cell.jobs.end());
  }
  pred.commit();

  std::printf("measuring h_max: %zu bisections over %d threads, floor %g s, ceiling %g s\n", jobs.size(), sweep.threads,
              sweep.h_floor, sweep.h_ceiling);
  for (const Job& job : jobs)
    if (job.skipped) std::printf("  K = %-7g D = %-3g %-17s %s\n", job.K, job.D, job.method.c_str(), job.outcome.c_str());
  std::mutex print;
  cloth::run_in_parallel(jobs.size(), sweep.threads, [&](std::size_t j) {
    cloth::throw_if_interrupted();
    Job& job = jobs[j];
    if (job.skipped) return;
    const double start = cloth::thread_cpu_seconds();  // the job runs on this thread alone (program/timing.hpp)
    const SceneParams params = cloth::with_K_and_D(scene, job.K, job.D);
    if (job.method == "implicit_euler") probe_implicit(params, sweep, job);
    else measure(params, sweep, stages(stability_model(job.method)), job);
    const std::lock_guard<std::mutex> lock(print);
    std::printf("  measured K = %-7g D = %-3g %-17s h_max in [%.4g, %.4g] (%d runs, %.2f s processor time)\n", job.K,
                job.D, job.method.c_str(), job.h, job.h_fail, job.runs, cloth::thread_cpu_seconds() - start);
    if (!job.outcome.empty()) std::printf("    %s\n", job.outcome.c_str());
  });

  cloth::OutputFile measured(dir + "/measured.dat");
  std::fprintf(measured.get(),
               "# K D method h_bounded h_unbounded runs (geometric mean plotted; 0: not found in [%g, %g]; "
               "runs 0: not measured)\n", sweep.h_floor, sweep.h_ceiling);
  for (const Job& job : jobs)
    std::fprintf(measured.get(), "%g %g %s %.6g %.6g %d\n", job.K, job.D, job.method.c_str(), job.h, job.h_fail, job.runs);
  measured.commit();
  write_hmax_table(dir + "/hmax_table.md", jobs, sweep, command);
  cloth::OutputFile implicit(dir + "/implicit_euler.txt");
  for (const Job& job : jobs)
    if (job.method == "implicit_euler") {
      const std::string line = "K = " + cloth::format_number(job.K) + ", D = " + cloth::format_number(job.D) + ": " + job.outcome;
      std::fputs(wrapped(line).c_str(), implicit.get());
    }
  implicit.commit();
  const auto skipped = std::count_if(jobs.begin(), jobs.end(), [](const Job& j) { return j.skipped; });
  return {{"sweep_jobs", std::to_string(jobs.size())}, {"sweep_jobs_not_measured", std::to_string(skipped)}};
}

}  // namespace ch07
