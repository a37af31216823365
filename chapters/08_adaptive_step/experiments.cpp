// The studies of Chapter 8 (experiments.hpp). Every file is written through cloth::OutputFile; the tables the
// page shows are written as fragments (program/fragment.hpp).
#include "experiments.hpp"

#include "base/format_number.hpp"
#include "integrators/adaptive_simulate.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/order_conditions.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/output_kinds.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

// Every attempt of dopri5 on the report's cloth, with the shortest spring at the state it starts from: where the
// controller shrinks h and where it rejects. Both controllers; pairs.dat sums up every pair with both.
void hard_case(const Options& opt, double tol, const std::string& command) {
  const Scene scene(opt.scene);
  ForceField field(scene);
  RunSettings run = opt.run;
  run.t_end = 1.0;
  Vector all(3 * scene.particle_count());
  OutputFile out(opt.run.out_dir + "/hard_case.dat");
  std::fprintf(out.get(), "# controller t h error accepted shortest_l_over_L0  (dopri5, rtol = atol = %g; blocks by "
                          "controller)\n", tol);
  MarkdownTable table({"controller", "accepted", "rejected", "rejected with a spring below L0/10", "evaluations",
                       "smallest step [s]", "largest step [s]", "first step below 1e-3 s at t [s]"},
                      "lrrrrrrr");
  // [hard_case]
  for (const ControllerKind controller : {ControllerKind::pi, ControllerKind::elementary}) {
    EmbeddedRungeKutta rk(field, embedded_tableau_from_argument("dopri5"));
    long long rejected_near_zero = 0;
    double first_short = -1;
    const AdaptiveResult r = adaptive_simulate(
        rk, run, with_tolerance(tol, controller), /*record=*/false,
        [&](const StepAttempt& a, const Vector& x, const Vector&) {
          const double shortest = shortest_spring(scene, x, all);
          if (!a.accepted && shortest < 0.1) ++rejected_near_zero;
          if (a.accepted && a.h < 1e-3 && first_short < 0) first_short = a.t;
          std::fprintf(out.get(), "%s %.10f %.6e %.6e %d %.6e\n", controller_name(controller), a.t, a.h, a.error,
                       a.accepted ? 1 : 0, shortest);
        });
    // [hard_case]
    throw_if_interrupted();  // an interrupted study writes none of its files: no table lists an unfinished run
    std::fprintf(out.get(), "\n\n");
    table.add_row({controller_name(controller), std::to_string(r.accepted), std::to_string(r.rejected),
                   std::to_string(rejected_near_zero), std::to_string(r.counters.rhs_evaluations),
                   format_number(r.smallest_step, 2), format_number(r.largest_step, 2),
                   first_short < 0 ? "-" : format_fixed(first_short, 2)});
  }
  out.commit();
  write_table_fragment(opt.run.out_dir + "/hard_case.md", table, command);
}

void pair_summary(const Options& opt, const std::vector<double>& tolerances, const std::string& command) {
  const Scene scene(opt.scene);
  ForceField field(scene);
  RunSettings run = opt.run;
  run.t_end = 1.0;
  OutputFile out(opt.run.out_dir + "/pairs.dat");
  std::fprintf(out.get(), "# pair controller tol accepted rejected evaluations smallest_h largest_h status\n");
  MarkdownTable table({"pair", "tolerance", "PI: accepted", "rejected", "evaluations", "elementary: accepted",
                       "rejected", "evaluations"},
                      "lrrrrrrr");
  for (const Method* row : methods_of(MethodFamily::embedded_runge_kutta))
    for (const double tol : tolerances) {
      std::vector<std::string> cells = {"`" + row->name + "`", format_number(tol)};
      for (const ControllerKind controller : {ControllerKind::pi, ControllerKind::elementary}) {
        const ButcherTableau& t = *row->tableau;
        EmbeddedRungeKutta rk(field, t);
        const AdaptiveResult r = adaptive_simulate(rk, run, with_tolerance(tol, controller), /*record=*/false);
        throw_if_interrupted();
        std::fprintf(out.get(), "%s %s %g %lld %lld %lld %.3e %.3e %s\n", t.name.c_str(), controller_name(controller),
                     tol, r.accepted, r.rejected, r.counters.rhs_evaluations, r.smallest_step, r.largest_step,
                     r.status == RunStatus::ok ? "ok" : "failed");
        const bool ok = r.status == RunStatus::ok;
        cells.push_back(ok ? std::to_string(r.accepted) : "failed");
        cells.push_back(ok ? std::to_string(r.rejected) : "-");
        cells.push_back(ok ? std::to_string(r.counters.rhs_evaluations) : "-");
      }
      table.add_row(cells);
    }
  out.commit();
  write_table_fragment(opt.run.out_dir + "/controllers.md", table, command);
}

// How closely the estimate check looks: every pair at rtol = atol = `tol`, and each accepted step taken again in
// `substeps` steps for the true error.
struct CheckPlan {
  double tol = 1e-5;
  int substeps = 64;
};

// Each pair's estimate against the true local error of its accepted steps on the cloth: every accepted step is
// taken again from the same state with plan.substeps steps of dopri5's fifth-order row, and the difference from
// the pair's candidate is measured in the same norm. Steps whose true error exceeds 10 tolerances while the
// estimate accepted them are steps the estimate did not see.
void estimate_check(const Options& opt, const CheckPlan& plan, const std::string& command) {
  const double tol = plan.tol;
  const int substeps = plan.substeps;
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
  MarkdownTable table({"pair", "accepted steps", "true error > 10 tolerances", "of them with a spring below L0/5",
                       "largest true error [tolerances]", "largest true / estimated"},
                      "lrrrrr");
  // [estimate_check]
  EmbeddedRungeKutta reference(reference_field, embedded_tableau_from_argument("dopri5"));
  for (const Method* row : methods_of(MethodFamily::embedded_runge_kutta)) {
    const ButcherTableau& t = *row->tableau;
    EmbeddedRungeKutta rk(field, t);
    Vector xr(scene.dof_count()), vr(scene.dof_count());
    long long accepted = 0, blind = 0, blind_near_zero = 0;
    double worst = 0, worst_ratio = 0;
    adaptive_simulate(rk, run, with_tolerance(tol, ControllerKind::pi), /*record=*/false,
                      [&](const StepAttempt& a, const Vector& x, const Vector& v) {
                        if (!a.accepted) return;
                        xr = x, vr = v;
                        for (int k = 0; k < substeps; ++k) reference.step(a.h / substeps, xr, vr);
                        const double truth = error_norm(rk.candidate_x() - xr, rk.candidate_v() - vr, x, v,
                                                        rk.candidate_x(), rk.candidate_v(), tolerances);
                        const double shortest = shortest_spring(scene, x, all);
                        ++accepted;
                        if (truth > 10) ++blind, blind_near_zero += shortest < 0.2 ? 1 : 0;
                        worst = std::max(worst, truth);
                        worst_ratio = std::max(worst_ratio, truth / std::max(a.error, 1e-3));
                        std::fprintf(out.get(), "%s %.10f %.6e %.6e %.6e %.6e\n", t.name.c_str(), a.t, a.h, a.error,
                                     truth, shortest);
                      });
    // [estimate_check]
    throw_if_interrupted();
    table.add_row({"`" + t.name + "`", std::to_string(accepted), std::to_string(blind), std::to_string(blind_near_zero),
                   format_number(worst, 2), format_number(worst_ratio, 2)});
    std::fprintf(out.get(), "\n\n");
    std::fprintf(summary.get(), "%s %lld %lld %.3e %.3e\n", t.name.c_str(), accepted, blind, worst, worst_ratio);
    std::printf("estimate check %-10s tol %g: %lld accepted steps, %lld with a true error above 10 tolerances, "
                "worst %.3g tolerances, worst true/estimate %.3g\n",
                t.name.c_str(), tol, accepted, blind, worst, worst_ratio);
  }
  out.commit();
  summary.commit();
  write_table_fragment(opt.run.out_dir + "/estimate_check.md", table, command);
}

}  // namespace

OutputList experiment_outputs() {
  using namespace cloth::output_kinds;
  return {{"pairs.md", fragment, "the registry's pairs with the residuals of their order conditions"},
          {"order_conditions.md", fragment, "the order conditions up to order 4"},
          {"tree_counts.md", fragment, "the number of rooted trees by order"},
          {"hard_case.dat", figure, "every attempt of dopri5 on the hard case, both controllers"},
          {"hard_case.md", fragment, "the controllers on the hard case"},
          {"pairs.dat", data, "every pair with both controllers at every tolerance"},
          {"controllers.md", fragment, "the controllers' steps and evaluations, pair by pair"},
          {"jump_response.dat", figure, "each pair's true error and estimate for a jump inside a step"},
          {"jump_response.md", fragment, "how each pair's estimate answers a jump"},
          {"estimate_check.dat", figure, "each accepted step's estimate against its true local error"},
          {"estimate_summary.dat", data, "per pair: accepted steps, blind steps, worst errors"},
          {"estimate_check.md", fragment, "each pair's estimate against the true local error"}};
}

void run_experiments(const Options& opt, bool quick, const std::string& command) {
  pairs_table(opt.run.out_dir, command);
  conditions_table(opt.run.out_dir, command);
  hard_case(opt, 1e-6, command);
  throw_if_interrupted();
  pair_summary(opt, quick ? std::vector<double>{1e-4, 1e-6} : std::vector<double>{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8},
               command);
  throw_if_interrupted();
  jump_response(opt, command);
  estimate_check(opt, {.tol = 1e-5, .substeps = quick ? 32 : 64}, command);
}

}  // namespace ch08
