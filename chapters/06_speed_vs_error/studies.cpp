// The studies of Chapter 6 (see studies.hpp). Runs are timed in-process, without I/O inside the timed region.
#include "studies.hpp"

#include "timing.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/adaptive_simulate.hpp"
#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "model/report_cases.hpp"
#include "program/interrupt.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace ch06 {

using namespace cloth;

namespace {

// The implicit rows' settings: CG needs the definite matrix; the direct path is Chapter 4's default, the exact
// Jacobian with the block factorization it calls for (LDL^T when undamped, LDU when the damper makes it
// non-symmetric).
MethodSettings implicit_settings(bool cg, NewtonVariant variant) {
  MethodSettings s;
  s.newton.solver = cg ? LinearSolverKind::cg : LinearSolverKind::automatic;
  s.newton.treatment = cg ? StiffnessTreatment::definite : StiffnessTreatment::exact;
  s.newton.variant = variant;
  return s;
}

}  // namespace

double max_particle_distance(const Vector& a, const Vector& b) {
  double worst = 0;
  for (Eigen::Index k = 0; k + 2 < a.size(); k += 3) worst = std::max(worst, (a.segment<3>(k) - b.segment<3>(k)).norm());
  return worst;
}

std::unique_ptr<OutputFile> open(const Sink& sink, const std::string& name, const char* header) {
  auto file = std::make_unique<OutputFile>(sink.dir + "/" + name);
  std::fprintf(file->get(), "%s\n", header);
  return file;
}

ShortestSpring shortest_spring(const Scene& scene, const Vector& x, Vector& all) {
  scene.all_positions(x, all);
  ShortestSpring out;
  const auto& springs = scene.springs().springs;
  for (int s = 0; s < static_cast<int>(springs.size()); ++s) {
    const Spring& sp = springs[static_cast<std::size_t>(s)];
    const int p = scene.particle_of_slot(sp.p), q = scene.particle_of_slot(sp.q);
    const double l = (all.segment<3>(3 * p) - all.segment<3>(3 * q)).norm() / sp.rest_length;
    if (l < out.length_over_rest) out.length_over_rest = l, out.spring = s;
  }
  return out;
}

const std::vector<SweepMethod>& sweep_methods() {
  static const std::vector<SweepMethod> rows = {
      {"explicit_euler", "explicit_euler", {}},
      {"symplectic_euler", "symplectic_euler", {}},
      {"heun", "heun", {}},
      {"rk4", "rk4", {}},
      {"rule38", "rule38", {}},
      {"implicit_euler_direct", "implicit_euler", implicit_settings(false, NewtonVariant::full)},
      {"implicit_euler_cg", "implicit_euler", implicit_settings(true, NewtonVariant::full)},
      {"implicit_euler_1newton_direct", "implicit_euler", implicit_settings(false, NewtonVariant::one)},
      {"implicit_euler_1newton_cg", "implicit_euler", implicit_settings(true, NewtonVariant::one)}};
  return rows;
}

const SweepMethod& sweep_method(const std::string& label) {
  std::string labels;
  for (const SweepMethod& m : sweep_methods()) {
    if (m.label == label) return m;
    labels += (labels.empty() ? "" : ", ") + m.label;
  }
  throw InputError("unknown sweep method '" + label + "': expected one of " + labels);
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
  for (long long k = 0; k < steps; ++k) {
    throw_if_interrupted();  // Ctrl-C ends the program between two steps (program/interrupt.hpp)
    if (!stepper.step(h, x, v)) {
      out.ok = false;
      out.message = "step failed at t = " + format_number(static_cast<double>(k + 1) * h, 3) + " s";
      return out;
    }
    if ((k + 1) % per_sample == 0) {
      if (!divergence_reason(x, v, radius).empty()) {
        out.ok = false;
        out.message = "diverged by t = " + format_number(static_cast<double>(k + 1) * h, 3) + " s";
        return out;
      }
      out.x[static_cast<std::size_t>((k + 1) / per_sample)] = x;
    }
  }
  return out;
}

namespace {

// The family of spring s (0 structural, 1 shear, 2 flexion).
int family_of(const SpringSet& springs, int s) {
  for (SpringFamily fam : all_spring_families)
    if (s >= springs.family[static_cast<int>(fam)].begin && s < springs.family[static_cast<int>(fam)].end)
      return static_cast<int>(fam);
  return 0;
}

// "a structural spring, (9,7)-(10,7)": its family and the grid indices of its two particles.
std::string spring_description(const Scene& scene, int s) {
  const Spring& sp = scene.springs().springs[static_cast<std::size_t>(s)];
  const int p = scene.particle_of_slot(sp.p), q = scene.particle_of_slot(sp.q), N = scene.grid().N;
  const char* const names[] = {"structural", "shear", "flexion"};
  return std::string("a ") + names[family_of(scene.springs(), s)] + " spring, (" + std::to_string(p / N) + "," +
         std::to_string(p % N) + ")-(" + std::to_string(q / N) + "," + std::to_string(q % N) + ")";
}

}  // namespace

// [near_zero]
// The smallest spring length relative to rest, l / L0, over the cloth and over time: where and when springs pass
// near zero length, where the force direction u = d / l turns abruptly and the right-hand side is not smooth.
NearZero near_zero_springs(const SceneParams& base, double T, double h, const Sink& sink) {
  const Scene scene(base);
  ForceField field(scene);
  const auto rk4 = make_stepper("rk4", field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  Vector all(3 * scene.particle_count());
  const auto steps = static_cast<long long>(std::llround(T / h));
  const auto file = open(sink, "near_zero.dat", "# t min_l_over_L0 family(0 structural,1 shear,2 flexion) i_p j_p i_q j_q");
  std::FILE* const f = file->get();
  NearZero out;
  out.h = h;
  int spring_min = -1;
  const auto& springs = scene.springs();
  for (long long k = 0; k <= steps; ++k) {
    throw_if_interrupted();
    if (k > 0) rk4->step(h, x, v);
    const auto [worst, which] = shortest_spring(scene, x, all);
    const Spring& sp = springs.springs[static_cast<std::size_t>(which)];
    const int family = family_of(springs, which);
    const int p = scene.particle_of_slot(sp.p), q = scene.particle_of_slot(sp.q);
    const int N = scene.grid().N;
    std::fprintf(f, "%.6f %.6e %d %d %d %d %d\n", k * h, worst, family, p / N, p % N, q / N, q % N);
    out.t.push_back(k * h), out.shortest.push_back(worst);
    if (worst < out.smallest) out.smallest = worst, out.t_smallest = k * h, spring_min = which;
    if (k * h <= 1.0 + 1e-12) {
      std::fprintf(sink.table, "near_zero K%g_D%g - %.6f - - %.6e - - - - - - ok\n", base.stiffness, base.damping,
                   k * h, worst);
    }
  }
  file->commit();
  out.spring = spring_description(scene, spring_min);
  std::printf("near-zero springs (K %g, D %g, rk4 h %g): smallest l/L0 = %.3e at t = %.4f s, %s\n", base.stiffness,
              base.damping, h, out.smallest, out.t_smallest, out.spring.c_str());
  return out;
}
// [near_zero]

// [sensitivity]
// Two RK4 runs whose initial positions differ by 1e-12 m in one coordinate (a particle near the middle, in z):
// the ratio of their largest particle distance to 1e-12 is how much the problem amplifies a perturbation, the
// condition number of the solution at time t; no method can be checked more accurately than eps times it.
std::vector<Sensitivity> sensitivity(const SceneParams& base, const std::vector<Config>& configs, double h,
                                     const Sink& sink) {
  const auto file = open(sink, "sensitivity.dat", "# config K D t amplification  (blocks by config)");
  std::FILE* const f = file->get();
  const double delta = 1e-12;
  std::vector<Sensitivity> out;
  for (const Config& c : configs) {
    Sensitivity& series = out.emplace_back(Sensitivity{c.name, {}, {}});
    const Scene scene(with_K_and_D(base, c.K, c.D));
    ForceField fa(scene), fb(scene);
    const auto a = make_stepper("rk4", fa), b = make_stepper("rk4", fb);
    Vector xa = scene.initial_positions(), va = scene.initial_velocities();
    Vector xb = xa, vb = va;
    xb[3 * (scene.free_count() / 2) + 2] += delta;
    const double T = 1.0;
    const auto steps = static_cast<long long>(std::llround(T / h));
    const long long every = std::max(1LL, steps / 200);
    std::fprintf(f, "# %s\n", c.name.c_str());
    for (long long k = 0; k <= steps; ++k) {
      throw_if_interrupted();
      if (k > 0) a->step(h, xa, va), b->step(h, xb, vb);
      if (k % every == 0) {
        const double amp = max_particle_distance(xa, xb) / delta;
        series.t.push_back(k * h), series.amplification.push_back(amp);
        std::fprintf(f, "%s %g %g %.6f %.6e\n", c.name.c_str(), c.K, c.D, k * h, amp);
        std::fprintf(sink.table, "sensitivity %s - %.6f - - - %.6e - - - - - ok\n", c.name.c_str(), k * h, amp);
      }
    }
    std::fprintf(f, "\n\n");
  }
  file->commit();
  return out;
}
// [sensitivity]

// [reference]
// The reference: RK4 with 2^k_ref steps, checked against the 3/8 rule (a different fourth-order method) with
// twice as many. Their largest sampled difference is its credential: every error plotted must exceed it 100x.
Trajectory reference(const SceneParams& base, const Config& c, int samples, int k_ref, const Sink& sink,
                     ReferenceCheck& check) {
  const Scene scene(with_K_and_D(base, c.K, c.D));
  ForceField f1(scene), f2(scene);
  const auto rk4 = make_stepper("rk4", f1), rule38 = make_stepper("rule38", f2);
  const long long n = 1LL << k_ref;
  const Trajectory a = run_sampled(*rk4, c.T, n, samples);
  const Trajectory b = run_sampled(*rule38, c.T, 2 * n, samples);
  double agreement = 0;
  for (std::size_t j = 0; j < a.x.size(); ++j) agreement = std::max(agreement, max_particle_distance(a.x[j], b.x[j]));
  check = {c.name, n, agreement};
  std::printf("reference %s (K %g, D %g, T %g): rk4 with h = T/2^%d and rule38 with h = T/2^%d agree to %.2e m\n",
              c.name.c_str(), c.K, c.D, c.T, k_ref, k_ref + 1, agreement);
  std::fprintf(sink.table, "reference %s rk4_vs_rule38 %.6g %lld - %.6e - - - - - - %s\n", c.name.c_str(),
               c.T / static_cast<double>(n), n, agreement, a.ok && b.ok ? "ok" : "failed");
  return b;
}
// [reference]

namespace {

// A run of the sweep, kept: its line in wp_<config>.dat and in speed_vs_error.dat, or its `dropped` row.
void record(const Sink& sink, std::FILE* f, std::vector<WorkPoint>& points, const WorkPoint& p) {
  const StepCounters& n = p.counters;
  if (p.dropped) {
    if (p.why == "below_100x_reference_agreement")
      std::fprintf(sink.table, "dropped %s %s %.6g %lld - %.6e - - - - - - %s\n", p.config.c_str(), p.method.c_str(),
                   p.h, p.steps, p.error, p.why.c_str());
    else {
      std::fprintf(sink.table, "dropped %s %s %.6g %lld - - - - - - - - %s\n", p.config.c_str(), p.method.c_str(), p.h,
                   p.steps, p.why.c_str());
      std::fprintf(f, "# dropped h = %g: %s\n", p.h, p.why.c_str());
    }
  } else {
    std::fprintf(f, "%s %.6e %lld %.6e %.6e %.6e %lld %lld %lld %lld %lld\n", p.method.c_str(), p.h, p.steps, p.seconds,
                 p.error, p.error_rms, n.rhs_evaluations, n.jacobian_assemblies, n.factorizations, n.cg_iterations,
                 n.newton_iterations);
    std::fprintf(sink.table, "wp %s %s %.6e %lld %.6e %.6e %.6e %lld %lld %lld %lld %lld ok\n", p.config.c_str(),
                 p.method.c_str(), p.h, p.steps, p.seconds, p.error, p.error_rms, n.rhs_evaluations,
                 n.jacobian_assemblies, n.factorizations, n.cg_iterations, n.newton_iterations);
    std::fflush(f);
  }
  points.push_back(p);
}

}  // namespace

// [work_precision]
std::vector<WorkPoint> work_precision(const SceneParams& base, const Config& c, const Trajectory& ref, int samples,
                                      int k_min, int k_max, double max_seconds, int runs, double ref_agreement,
                                      const Sink& sink) {
  const Scene scene(with_K_and_D(base, c.K, c.D));
  std::vector<WorkPoint> points;
  const auto file = open(sink, "wp_" + c.name + ".dat",
                      "# method h steps seconds err_max_T err_rms rhs assemblies factorizations cg_iterations "
                      "newton_iterations  (blocks by method)");
  std::FILE* const f = file->get();
  for (const SweepMethod& row : sweep_methods()) {
    const std::string& method = row.label;
    std::fprintf(f, "# %s\n", method.c_str());
    for (int k = k_min; k <= k_max; ++k) {
      const long long steps = 1LL << k;
      const double h = c.T / static_cast<double>(steps);
      ForceField field(scene);
      auto stepper = row.stepper(field);
      // The error run (also the warm-up of the timing runs).
      const auto t0 = std::chrono::steady_clock::now();
      Trajectory traj = run_sampled(*stepper, c.T, steps, samples);
      const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      WorkPoint point{c.name, method, h, 0, steps, 0, 0, 0, stepper->counters(), false, ""};
      if (!traj.ok) {
        point.dropped = true, point.why = traj.message;
        record(sink, f, points, point);
        continue;
      }
      point.error = max_particle_distance(traj.x.back(), ref.x.back());
      double sum2 = 0;
      long long terms = 0;
      for (std::size_t j = 1; j < traj.x.size(); ++j) {
        sum2 += (traj.x[j] - ref.x[j]).squaredNorm();
        terms += traj.x[j].size() / 3;
      }
      point.error_rms = std::sqrt(sum2 / static_cast<double>(terms));
      // An error within 100x of the reference's own uncertainty is not a measurement: listed, not plotted.
      if (point.error < 100 * ref_agreement) {
        point.dropped = true, point.why = "below_100x_reference_agreement";
        record(sink, f, points, point);
        break;
      }
      // Timing: the median of `runs` repeated runs (fewer when one run is already long: then 1 is the median).
      const int n_runs = first > max_seconds / 5 ? 1 : runs;
      point.seconds = n_runs == 1 ? first : median_seconds([&] {
        ForceField fresh(scene);
        auto s = row.stepper(fresh);
        run_sampled(*s, c.T, steps, samples);
      }, n_runs, 0).wall;
      record(sink, f, points, point);
      if (point.error < 1e-9 || first > max_seconds) break;  // accurate enough, or expensive enough
    }
    std::fprintf(f, "\n\n");
  }
  // Chapter 8's adaptive Dormand-Prince beside the fixed steps: one run per tolerance rtol = atol = 10^-j. Its
  // h is the mean step T / (accepted steps); it samples no intermediate times, so its err_rms is its error at T.
  std::fprintf(f, "# dopri5_adaptive\n");
  RunSettings run;
  run.t_end = c.T;
  run.stop = &interrupt_flag();
  for (int j = 2; j <= 10; ++j) {
    throw_if_interrupted();
    const double tol = std::pow(10.0, -j);
    AdaptiveSettings settings;
    settings.tolerances = {tol, tol};
    ForceField field(scene);
    EmbeddedRungeKutta rk(field, embedded_tableau_from_argument("dopri5"));
    const auto t0 = std::chrono::steady_clock::now();
    const AdaptiveResult r = adaptive_simulate(rk, run, settings, false);
    const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double h = r.accepted > 0 ? c.T / static_cast<double>(r.accepted) : 0.0;
    WorkPoint point{c.name, "dopri5_adaptive", h, tol, r.accepted, 0, 0, 0, r.counters, false, ""};
    if (r.status != RunStatus::ok) {
      point.dropped = true, point.why = r.message;
      record(sink, f, points, point);
      continue;
    }
    point.error = point.error_rms = max_particle_distance(r.x, ref.x.back());
    if (point.error < 100 * ref_agreement) {
      point.dropped = true, point.why = "below_100x_reference_agreement";
      record(sink, f, points, point);
      break;
    }
    const int n_runs = first > max_seconds / 5 ? 1 : runs;
    point.seconds = n_runs == 1 ? first : median_seconds([&] {
      ForceField fresh(scene);
      EmbeddedRungeKutta again(fresh, embedded_tableau_from_argument("dopri5"));
      adaptive_simulate(again, run, settings, false);
    }, n_runs, 0).wall;
    record(sink, f, points, point);
    if (point.error < 1e-9 || first > max_seconds) break;
  }
  std::fprintf(f, "\n\n");
  file->commit();
  return points;
}
// [work_precision]

namespace {

// A grid size of the scaling study, kept: its line in scaling.dat and speed_vs_error.dat, and on the console.
void record(const Sink& sink, std::FILE* f, std::vector<ScalingPoint>& points, const ScalingPoint& p, double h) {
  std::fprintf(f, "%s %d %d %.6e %.6e %.6e %.6e %.3f %.2f %.6e\n", p.method.c_str(), p.size, p.springs,
               p.wall_per_step, p.assembly_per_step, p.factorization_per_step, p.solve_per_step, p.newton_per_step,
               p.cg_per_solve, p.cpu_per_step);
  std::fprintf(sink.table, "scaling %dx%d %s %.6g %d %.6e - - - - - - - ok\n", p.size, p.size, p.method.c_str(), h,
               p.springs, p.wall_per_step);
  std::fflush(f);
  std::printf("scaling %-20s %4dx%-4d %8d springs %10.3f ms/step (assembly %.3f, factorization %.3f, solve "
              "%.3f ms), %.2f Newton/step, %.1f CG/solve\n",
              p.method.c_str(), p.size, p.size, p.springs, 1e3 * p.wall_per_step, 1e3 * p.assembly_per_step,
              1e3 * p.factorization_per_step, 1e3 * p.solve_per_step, p.newton_per_step, p.cg_per_solve);
  points.push_back(p);
}

}  // namespace

// [scaling]
// Cost of one step against the grid size, at the report's h = 0.01 for the implicit methods and h = 1e-3 for
// the explicit ones (the step changes the work per step only through Newton and CG iteration counts).
std::vector<ScalingPoint> scaling(const SceneParams& base, const std::vector<int>& sizes, int runs,
                                  double max_step_seconds, const Sink& sink) {
  const auto file = open(sink, "scaling.dat",
                      "# method grid springs seconds_per_step assembly factorization solve newton_per_step "
                      "cg_per_solve cpu_seconds_per_step  (blocks by method)");
  std::FILE* const f = file->get();
  std::vector<ScalingPoint> points;
  for (const std::string method : {"explicit_euler", "rk4", "implicit_euler_direct", "implicit_euler_cg"}) {
    std::fprintf(f, "# %s\n", method.c_str());
    for (int size : sizes) {
      throw_if_interrupted();
      SceneParams p = base;
      p.grid.M = p.grid.N = size;
      const Scene scene(p);
      ForceField field(scene);
      auto stepper = sweep_method(method).stepper(field);
      const bool implicit = find_method(sweep_method(method).method).family == MethodFamily::implicit_runge_kutta;
      const double h = implicit ? 0.01 : 1e-3;
      // Start from the state at t = 0.05 s, where the cloth is moving and stretched.
      Vector x = scene.initial_positions(), v = scene.initial_velocities();
      for (int k = 0; k < 5; ++k) stepper->step(h, x, v);
      const Vector x0 = x, v0 = v;
      const int steps = implicit ? 3 : 10;
      auto* ie = dynamic_cast<ImplicitEuler*>(stepper.get());
      if (ie) ie->reset_timing();
      stepper->reset_counters();
      const auto start = std::chrono::steady_clock::now();
      const Seconds t = median_seconds(
          [&] {
            x = x0, v = v0;
            for (int k = 0; k < steps; ++k) stepper->step(h, x, v);
          },
          runs, 1);
      // Per step: the median run's, and the mean over every step taken, which the parts of an implicit step are.
      const StepCounters& n = stepper->counters();
      const auto per_step = 1.0 / static_cast<double>(n.steps);
      ScalingPoint point{method, size, scene.springs().size(), t.wall / steps, t.cpu / steps};
      point.mean_wall_per_step =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * per_step;
      if (ie) {
        point.assembly_per_step = ie->timing().assembly * per_step;
        point.factorization_per_step = ie->timing().factorization * per_step;
        point.solve_per_step = ie->timing().solve * per_step;
      }
      point.newton_per_step = static_cast<double>(n.newton_iterations) * per_step;
      point.cg_per_solve =
          n.linear_solves > 0 ? static_cast<double>(n.cg_iterations) / static_cast<double>(n.linear_solves) : 0.0;
      record(sink, f, points, point, h);
      if (point.wall_per_step > max_step_seconds) break;  // larger grids would take minutes
    }
    std::fprintf(f, "\n\n");
  }
  file->commit();
  return points;
}
// [scaling]

}  // namespace ch06
