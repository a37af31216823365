// Chapter 6's work-precision sweep (see sweep.hpp). Runs are timed in-process, with no input or output inside
// the timed region; how and why is the appendix on measuring.
#include "sweep.hpp"

#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"
#include "integrators/adaptive_simulate.hpp"
#include "integrators/method_registry.hpp"
#include "model/report_cases.hpp"
#include "integrators/simulate.hpp"
#include "program/interrupt.hpp"
#include "program/method_flags.hpp"

#include <cmath>
#include <functional>

namespace ch06 {

using namespace cloth;

const std::vector<std::string>& sweep_methods() {
  static const std::vector<std::string> names = {
      "explicit_euler", "symplectic_euler", "heun", "rk4", "rule38", "implicit_euler", "implicit_euler/cg",
      "implicit_euler/one", "implicit_euler/one/cg", "dopri5"};
  return names;
}

std::unique_ptr<Stepper> make_sweep_stepper(const std::string& name, ForceField& field) {
  Configuration c = parse_configuration(name);
  c.settings.newton.treatment =
      c.jacobian.value_or(default_treatment(c.settings.newton.solver, /*nonsymmetric=*/false));
  return make_stepper(c.method, field, c.settings);
}

std::unique_ptr<OutputFile> open(const Sink& sink, const std::string& name, const char* header) {
  auto file = std::make_unique<OutputFile>(sink.dir + "/" + name);
  std::fprintf(file->get(), "%s\n", header);
  return file;
}

Trajectory run_sampled(Stepper& stepper, double T, long long steps, int samples) {
  const Scene& scene = stepper.field().scene();
  Trajectory out;
  out.x.assign(static_cast<std::size_t>(samples) + 1, Vector(scene.dof_count()));
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  out.x[0] = x;
  const double h = T / static_cast<double>(steps);
  const long long per_sample = steps / samples;
  const double radius = divergence_radius(scene, T);
  const auto stop = [&](long long k, const char* what) {  // "step failed at t = ...", "diverged by t = ..."
    out.ok = false;
    out.message = std::string(what) + " t = " + format_number(static_cast<double>(k + 1) * h, 3) + " s";
    return out;
  };
  for (long long k = 0; k < steps; ++k) {
    throw_if_interrupted();  // Ctrl-C ends the program between two steps (program/interrupt.hpp)
    if (!stepper.step(h, x, v)) return stop(k, "step failed at");
    if ((k + 1) % per_sample != 0) continue;
    if (!divergence_reason(x, v, radius).empty()) return stop(k, "diverged by");
    out.x[static_cast<std::size_t>((k + 1) / per_sample)] = x;
  }
  return out;
}

// [reference]
// The reference: RK4 with 2^k_ref steps, checked against the 3/8 rule (a different fourth-order method) with
// twice as many. Their largest sampled difference is its credential: every error plotted must exceed it 100x.
Trajectory reference(const SceneParams& base, const Config& c, const SweepPlan& plan, const Sink& sink,
                     ReferenceCheck& check) {
  const Scene scene(with_K_and_D(base, c.K, c.D));
  ForceField f1(scene), f2(scene);
  const auto rk4 = make_stepper("rk4", f1), rule38 = make_stepper("rule38", f2);
  const int k_ref = plan.k_reference;
  const long long n = 1LL << k_ref;
  const Trajectory a = run_sampled(*rk4, c.T, n, plan.samples);
  const Trajectory b = run_sampled(*rule38, c.T, 2 * n, plan.samples);
  double agreement = 0;
  for (std::size_t j = 0; j < a.x.size(); ++j) agreement = std::max(agreement, largest_distance(a.x[j], b.x[j]));
  check = {c.name, n, agreement};
  std::printf("reference %s (K %g, D %g, T %g): rk4 with h = T/2^%d and rule38 with h = T/2^%d agree to %.2e m\n",
              c.name.c_str(), c.K, c.D, c.T, k_ref, k_ref + 1, agreement);
  std::fprintf(sink.table, "reference %s rk4_vs_rule38 %.6g %lld - %.6e - - - - - - %s\n", c.name.c_str(),
               c.T / static_cast<double>(n), n, agreement, a.ok && b.ok ? "ok" : "failed");
  return b;
}
// [reference]

namespace {

// One rung of a method's ladder, run once: what it sampled (every sampled time, or only T for the adaptive
// pair), its counters, and the step it took.
struct Rung {
  Trajectory run;
  StepCounters counters;
  long long steps = 0;
  double h = 0, tolerance = 0;
};

// A fixed-step method with h = T / 2^k.
Rung fixed_step_rung(const Scene& scene, const std::string& method, double T, int samples, int k) {
  ForceField field(scene);
  const auto stepper = make_sweep_stepper(method, field);
  const long long steps = 1LL << k;
  Rung r{run_sampled(*stepper, T, steps, samples), {}, steps, T / static_cast<double>(steps), 0};
  r.counters = stepper->counters();
  return r;
}

// Chapter 8's adaptive Dormand-Prince pair with rtol = atol = 10^-j. Its h is the mean step T / (accepted
// steps); it samples no intermediate times, so its RMS error is its error at T.
Rung adaptive_rung(const Scene& scene, double T, int j) {
  RunSettings run;
  run.t_end = T;
  run.stop = &interrupt_flag();
  AdaptiveSettings settings;
  const double tolerance = std::pow(10.0, -j);
  settings.tolerances = {tolerance, tolerance};
  ForceField field(scene);
  EmbeddedRungeKutta pair(field, embedded_tableau_from_argument("dopri5"));
  const AdaptiveResult a = adaptive_simulate(pair, run, settings, /*record=*/false);
  Rung r;
  r.run.x = {a.x};
  r.run.ok = a.status == RunStatus::ok;
  r.run.message = a.message;
  r.counters = a.counters;
  r.steps = a.accepted;
  r.h = a.accepted > 0 ? T / static_cast<double>(a.accepted) : 0.0;
  r.tolerance = tolerance;
  return r;
}

// The root mean square of the particles' distances from the reference over the sampled times after t = 0.
double rms_distance(const std::vector<Vector>& run, const std::vector<Vector>& ref) {
  double sum2 = 0;
  long long terms = 0;
  for (std::size_t j = 1; j < run.size(); ++j) {
    sum2 += (run[j] - ref[j]).squaredNorm();
    terms += run[j].size() / 3;
  }
  return std::sqrt(sum2 / static_cast<double>(terms));
}

// A run of the sweep, kept: its line in wp_<config>.dat and in speed_vs_error.dat, or its `dropped` row.
void record(const Sink& sink, std::FILE* f, const WorkPoint& p) {
  const StepCounters& n = p.counters;
  if (p.dropped) {
    const bool measured = p.error > 0;
    std::fprintf(sink.table, "dropped %s %s %.6g %lld - %s - - - - - - %s\n", p.config.c_str(), p.method.c_str(),
                 p.h, p.steps, measured ? format_number(p.error, 7).c_str() : "-", p.why.c_str());
    if (!measured) std::fprintf(f, "# dropped h = %g: %s\n", p.h, p.why.c_str());
    return;
  }
  std::fprintf(f, "%s %.6e %lld %.6e %.6e %.6e %lld %lld %lld %lld %lld %.6e\n", p.method.c_str(), p.h, p.steps,
               p.timing.fastest_cpu, p.error, p.error_rms, n.rhs_evaluations, n.jacobian_assemblies,
               n.factorizations, n.cg_iterations, n.newton_iterations, p.timing.slowest_cpu);
  std::fprintf(sink.table, "wp %s %s %.6e %lld %.6e %.6e %.6e %lld %lld %lld %lld %lld ok\n", p.config.c_str(),
               p.method.c_str(), p.h, p.steps, p.timing.fastest_cpu, p.error, p.error_rms, n.rhs_evaluations,
               n.jacobian_assemblies, n.factorizations, n.cg_iterations, n.newton_iterations);
  std::fflush(f);
}

}  // namespace

std::vector<WorkPoint> work_precision(const SceneParams& base, const Config& c, const Trajectory& ref,
                                      double ref_agreement, const SweepPlan& plan, const Sink& sink) {
  const Scene scene(with_K_and_D(base, c.K, c.D));
  std::vector<WorkPoint> points;
  const auto file = open(sink, "wp_" + c.name + ".dat",
                         "# method h steps cpu_seconds_fastest err_max_T err_rms rhs assemblies factorizations "
                         "cg_iterations newton_iterations cpu_seconds_slowest  (blocks by method)");
  std::FILE* const f = file->get();
  for (const std::string& method : sweep_methods()) {
    const bool adaptive = method == "dopri5";
    const std::function<Rung(int)> run_rung = [&](int rung) {
      return adaptive ? adaptive_rung(scene, c.T, rung) : fixed_step_rung(scene, method, c.T, plan.samples, rung);
    };
    std::fprintf(f, "# %s\n", method.c_str());
    const int first = adaptive ? plan.tolerance_min : plan.k_min, last = adaptive ? plan.tolerance_max : plan.k_max;
    // [work_precision]
    // Each method runs down its ladder (smaller steps, or tighter tolerances) until it is accurate to 1e-9 m, its
    // error reaches the reference's own uncertainty, or a run costs more than plan.max_seconds. The first run of
    // a rung measures the error and warms the caches; the timed runs repeat it whole.
    for (int rung = first; rung <= last; ++rung) {
      const double cpu_start = thread_cpu_seconds(), wall_start = wall_seconds();
      const Rung r = run_rung(rung);
      const double cpu = thread_cpu_seconds() - cpu_start, wall = wall_seconds() - wall_start;
      WorkPoint& p = points.emplace_back(WorkPoint{.config = c.name, .method = method, .h = r.h,
                                                   .tolerance = r.tolerance, .steps = r.steps, .counters = r.counters});
      if (!r.run.ok) {
        p.dropped = true, p.why = r.run.message;
        record(sink, f, p);
        continue;
      }
      p.error = largest_distance(r.run.x.back(), ref.x.back());
      p.error_rms = p.error;
      if (r.run.x.size() == ref.x.size()) p.error_rms = rms_distance(r.run.x, ref.x);
      // An error within 100x of the reference's own uncertainty is not a measurement: listed, not plotted.
      if (p.error < 100 * ref_agreement) {
        p.dropped = true, p.why = "below_100x_reference_agreement";
        record(sink, f, p);
        break;
      }
      const Timing once{.fastest_cpu = cpu, .median_cpu = cpu, .slowest_cpu = cpu, .fastest_wall = wall,
                        .median_wall = wall, .runs = 1};
      p.timing = cpu > plan.max_seconds / 5 ? once : time_runs([&] { (void)run_rung(rung); }, {.runs = plan.runs});
      record(sink, f, p);
      if (p.error < 1e-9 || cpu > plan.max_seconds) break;  // accurate enough, or expensive enough
    }
    // [work_precision]
    std::fprintf(f, "\n\n");
  }
  file->commit();
  return points;
}

}  // namespace ch06
