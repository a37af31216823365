// The studies of Chapter 8 (experiments.hpp). Every file is written through cloth::OutputFile.
#include "experiments.hpp"

#include "integrators/adaptive_simulate.hpp"
#include "integrators/embedded_tableaus.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace ch08 {

using namespace cloth;

namespace {

// The shortest spring's length over its rest length at the free positions x (`all`: scratch for every particle).
double shortest_spring(const Scene& scene, const Vector& x, Vector& all) {
  scene.all_positions(x, all);
  double shortest = 1e300;
  for (const Spring& sp : scene.springs().springs) {
    const int p = scene.particle_of_slot(sp.p), q = scene.particle_of_slot(sp.q);
    shortest = std::min(shortest, (all.segment<3>(3 * p) - all.segment<3>(3 * q)).norm() / sp.rest_length);
  }
  return shortest;
}

AdaptiveSettings with_tolerance(double tol, ControllerKind controller) {
  AdaptiveSettings s;
  s.tolerances = {tol, tol};
  s.controller = controller;
  return s;
}

// [hard_case]
// Every attempt of dopri5 on the report's cloth, with the shortest spring at the state it starts from: where the
// controller shrinks h and where it rejects. Both controllers; pairs.dat sums up every pair with both.
void hard_case(const Options& opt, double tol) {
  const Scene scene(opt.scene);
  ForceField field(scene);
  RunSettings run = opt.run;
  run.t_end = 1.0;
  Vector all(3 * scene.particle_count());
  OutputFile out(opt.run.out_dir + "/hard_case.dat");
  std::fprintf(out.get(), "# controller t h error accepted shortest_l_over_L0  (dopri5, rtol = atol = %g; blocks by "
                          "controller)\n", tol);
  for (const ControllerKind controller : {ControllerKind::pi, ControllerKind::elementary}) {
    EmbeddedRungeKutta rk(field, embedded_tableau_from_argument("dopri5"));
    adaptive_simulate(rk, run, with_tolerance(tol, controller), false,
                      [&](const StepAttempt& a, const Vector& x, const Vector&) {
                        std::fprintf(out.get(), "%s %.10f %.6e %.6e %d %.6e\n", controller_name(controller), a.t, a.h,
                                     a.error, a.accepted ? 1 : 0, shortest_spring(scene, x, all));
                      });
    std::fprintf(out.get(), "\n\n");
  }
  out.commit();
}

void pair_summary(const Options& opt, const std::vector<double>& tolerances) {
  const Scene scene(opt.scene);
  ForceField field(scene);
  RunSettings run = opt.run;
  run.t_end = 1.0;
  OutputFile out(opt.run.out_dir + "/pairs.dat");
  std::fprintf(out.get(), "# pair controller tol accepted rejected evaluations smallest_h largest_h status\n");
  for (const ButcherTableau& t : embedded_tableaus())
    for (const double tol : tolerances)
      for (const ControllerKind controller : {ControllerKind::pi, ControllerKind::elementary}) {
        EmbeddedRungeKutta rk(field, t);
        const AdaptiveResult r = adaptive_simulate(rk, run, with_tolerance(tol, controller), false);
        std::fprintf(out.get(), "%s %s %g %lld %lld %lld %.3e %.3e %s\n", t.name.c_str(), controller_name(controller),
                     tol, r.accepted, r.rejected, r.counters.rhs_evaluations, r.smallest_step, r.largest_step,
                     r.status == RunStatus::ok ? "ok" : "failed");
      }
  out.commit();
}
// [hard_case]

// [jump_response]
// A jump J in the acceleration at t0 + theta h, inside a step: stage i sees it when c_i > theta, so the step
// gains J h sum_{c_i > theta} b_i of velocity where the truth gains J h (1 - theta), and the estimate reports
// J h sum_{c_i > theta} (b_i - bhat_i). Per unit J h: the true error of the step and what the pair estimates.
void jump_response(const Options& opt) {
  OutputFile out(opt.run.out_dir + "/jump_response.dat");
  std::fprintf(out.get(), "# theta, then per pair: true_error estimate  (per unit J h; pairs in the order of "
                          "embedded_tableaus())\n");
  for (int k = 0; k <= 1000; ++k) {
    const double theta = (k + 0.5) / 1001.0;
    std::fprintf(out.get(), "%.6f", theta);
    for (const ButcherTableau& t : embedded_tableaus()) {
      double seen_b = 0, seen_d = 0;
      for (int i = 0; i < t.stages(); ++i)
        if (t.c[i] > theta) seen_b += t.b[i], seen_d += t.b[i] - t.b_hat[i];
      std::fprintf(out.get(), " %.6e %.6e", seen_b - (1 - theta), seen_d);
    }
    std::fprintf(out.get(), "\n");
  }
  out.commit();
}
// [jump_response]

// [estimate_check]
// Each pair's estimate against the true local error of its accepted steps on the cloth: every accepted step is
// taken again from the same state with `substeps` steps of dopri5's fifth-order row, and the difference from the
// pair's candidate is measured in the same norm. Steps whose true error exceeds 10 tolerances while the estimate
// accepted them are steps the estimate did not see.
void estimate_check(const Options& opt, double tol, int substeps) {
  const Scene scene(opt.scene);
  ForceField field(scene), reference_field(scene);
  RunSettings run = opt.run;
  run.t_end = 1.0;
  const Tolerances tolerances{tol, tol};
  Vector all(3 * scene.particle_count());
  OutputFile out(opt.run.out_dir + "/estimate_check.dat");
  OutputFile summary(opt.run.out_dir + "/estimate_summary.dat");
  std::fprintf(out.get(), "# pair t h estimate true_error shortest_l_over_L0  (rtol = atol = %g; blocks by pair)\n", tol);
  std::fprintf(summary.get(), "# pair accepted blind_steps(true > 10, estimate <= 1) worst_true worst_ratio_true_over_estimate\n");
  EmbeddedRungeKutta reference(reference_field, embedded_tableau_from_argument("dopri5"));
  for (const ButcherTableau& t : embedded_tableaus()) {
    EmbeddedRungeKutta rk(field, t);
    Vector xr(scene.dof_count()), vr(scene.dof_count());
    long long accepted = 0, blind = 0;
    double worst = 0, worst_ratio = 0;
    adaptive_simulate(rk, run, with_tolerance(tol, ControllerKind::pi), false,
                      [&](const StepAttempt& a, const Vector& x, const Vector& v) {
                        if (!a.accepted) return;
                        xr = x, vr = v;
                        for (int k = 0; k < substeps; ++k) reference.step(a.h / substeps, xr, vr);
                        const double truth = error_norm(rk.candidate_x() - xr, rk.candidate_v() - vr, x, v,
                                                        rk.candidate_x(), rk.candidate_v(), tolerances);
                        ++accepted;
                        if (truth > 10) ++blind;
                        worst = std::max(worst, truth);
                        worst_ratio = std::max(worst_ratio, truth / std::max(a.error, 1e-3));
                        std::fprintf(out.get(), "%s %.10f %.6e %.6e %.6e %.6e\n", t.name.c_str(), a.t, a.h, a.error,
                                     truth, shortest_spring(scene, x, all));
                      });
    std::fprintf(out.get(), "\n\n");
    std::fprintf(summary.get(), "%s %lld %lld %.3e %.3e\n", t.name.c_str(), accepted, blind, worst, worst_ratio);
    std::printf("estimate check %-10s tol %g: %lld accepted steps, %lld with a true error above 10 tolerances, "
                "worst %.3g tolerances, worst true/estimate %.3g\n",
                t.name.c_str(), tol, accepted, blind, worst, worst_ratio);
  }
  out.commit();
  summary.commit();
}
// [estimate_check]

}  // namespace

std::vector<std::string> experiment_outputs() {
  return {"hard_case.dat", "pairs.dat", "jump_response.dat", "estimate_check.dat", "estimate_summary.dat"};
}

void run_experiments(const Options& opt, bool quick) {
  hard_case(opt, 1e-6);
  throw_if_interrupted();
  pair_summary(opt, quick ? std::vector<double>{1e-4, 1e-6} : std::vector<double>{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8});
  throw_if_interrupted();
  jump_response(opt);
  estimate_check(opt, 1e-5, quick ? 32 : 64);
}

}  // namespace ch08
