// Predicted and measured h_max for Chapter 7.
#include "hmax.hpp"
#include "bisection.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "model/report_cases.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/parallel_runs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

// The predictions at each (D, K), independent of each other: computed on every thread, written in order to
// predicted.dat; returns the sweep's jobs, each with its predicted h as the first guess.
std::vector<Job> predict_jobs(const std::string& dir, const SceneParams& scene, const RestSpectrum& rest,
                              Equilibria& equilibria, const SweepSettings& sweep) {
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
  return jobs;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> hmax_sweep(const std::string& dir, const SceneParams& scene,
                                                            const RestSpectrum& rest, Equilibria& equilibria,
                                                            const SweepSettings& sweep, const std::string& command) {
  std::vector<Job> jobs = predict_jobs(dir, scene, rest, equilibria, sweep);  // predicted.dat
  measure_jobs(jobs, scene, sweep);  // each bracket, as it comes

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
