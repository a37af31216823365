// Chapter 7: h_max measured by bisection (see bisection.hpp).
#include "bisection.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "model/report_cases.hpp"
#include "program/interrupt.hpp"
#include "program/parallel_runs.hpp"
#include "program/timing.hpp"

#include <cstdio>
#include <mutex>

namespace ch07 {

using cloth::SceneParams;

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

// Brackets the boundary by doubling or halving from the guess, then bisects it geometrically.
// A run that would cost more than the budget is not made: halving then stops at the last h tried, and the job
// says so (bisection never needs one: it runs between two steps already afforded).
void bisect(const SceneParams& params, const SweepSettings& sweep, int stages, Job& job) {
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

}  // namespace

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

void measure_jobs(std::vector<Job>& jobs, const SceneParams& scene, const SweepSettings& sweep) {
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
    else bisect(params, sweep, stages(stability_model(job.method)), job);
    const std::lock_guard<std::mutex> lock(print);
    std::printf("  measured K = %-7g D = %-3g %-17s h_max in [%.4g, %.4g] (%d runs, %.2f s processor time)\n", job.K,
                job.D, job.method.c_str(), job.h, job.h_fail, job.runs, cloth::thread_cpu_seconds() - start);
    if (!job.outcome.empty()) std::printf("    %s\n", job.outcome.c_str());
  });
}

}  // namespace ch07
