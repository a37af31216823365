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
        rk, run, with_tolerance(tol, controller), false, [&](const StepAttempt& a, const Vector& x, const Vector&) {
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
        const AdaptiveResult r = adaptive_simulate(rk, run, with_tolerance(tol, controller), false);
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

// [jump_response]
// A jump J in the acceleration at t0 + theta h, inside a step: stage i sees it when c_i > theta, so the step
// gains J h sum_{c_i > theta} b_i of velocity where the truth gains J h (1 - theta), and the estimate reports
// J h sum_{c_i > theta} (b_i - bhat_i). Per unit J h: the true error of the step and what the pair estimates.
struct JumpResponse {
  double true_error, estimate;
};
JumpResponse response_to_jump(const ButcherTableau& t, double theta) {
  double seen_b = 0, seen_d = 0;
  for (int i = 0; i < t.stages(); ++i)
    if (t.c[i] > theta) seen_b += t.b[i], seen_d += t.b[i] - t.b_hat[i];
  return {seen_b - (1 - theta), seen_d};
}
// [jump_response]

// Every pair's response to a jump at 1001 instants across the step (jump_response.dat, the figure), and each
// pair's extremes (jump_response.md, the page's table).
void jump_response(const Options& opt, const std::string& command) {
  const std::vector<const Method*> pairs = methods_of(MethodFamily::embedded_runge_kutta);
  // Per pair: the largest true error, the largest estimate, and the largest estimate of a jump before 0.8 h.
  struct Extremes {
    double truth = 0, estimate = 0, early_estimate = 0;
  };
  std::vector<Extremes> worst(pairs.size());
  OutputFile out(opt.run.out_dir + "/jump_response.dat");
  std::fprintf(out.get(), "# theta, then per pair: true_error estimate  (per unit J h; pairs in the order of "
                          "the method registry)\n");
  for (int k = 0; k <= 1000; ++k) {
    const double theta = (k + 0.5) / 1001.0;
    std::fprintf(out.get(), "%.6f", theta);
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const JumpResponse r = response_to_jump(*pairs[p]->tableau, theta);
      std::fprintf(out.get(), " %.6e %.6e", r.true_error, r.estimate);
      Extremes& w = worst[p];
      w.truth = std::max(w.truth, std::abs(r.true_error));
      w.estimate = std::max(w.estimate, std::abs(r.estimate));
      if (theta < 0.8) w.early_estimate = std::max(w.early_estimate, std::abs(r.estimate));
    }
    std::fprintf(out.get(), "\n");
  }
  out.commit();
  MarkdownTable table({"pair", "largest true error [J h]", "largest estimate [J h]",
                       "largest estimate of a jump before 0.8 h [J h]"},
                      "lrrr");
  for (std::size_t p = 0; p < pairs.size(); ++p)
    table.add_row({"`" + pairs[p]->name + "`", format_number(worst[p].truth, 2), format_number(worst[p].estimate, 2),
                   format_number(worst[p].early_estimate, 2)});
  write_table_fragment(opt.run.out_dir + "/jump_response.md", table, command);
}

// Each pair's estimate against the true local error of its accepted steps on the cloth: every accepted step is
// taken again from the same state with `substeps` steps of dopri5's fifth-order row, and the difference from the
// pair's candidate is measured in the same norm. Steps whose true error exceeds 10 tolerances while the estimate
// accepted them are steps the estimate did not see.
void estimate_check(const Options& opt, double tol, int substeps, const std::string& command) {
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
    adaptive_simulate(rk, run, with_tolerance(tol, ControllerKind::pi), false,
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

// The registry's pairs as the page lists them, with the residuals of their order conditions: the largest over
// every condition of a row's own order and below (rounding), and the smallest largest-residual of the next order
// (the conditions the row does not satisfy).
void pairs_table(const std::string& dir, const std::string& command) {
  MarkdownTable table({"name", "pair", "stages", "orders (b, b-hat)", "FSAL", "evaluations per step",
                       "residual to its orders", "residual of the next order (b, b-hat)"},
                      "llrrlrrr");
  for (const Method* m : methods_of(MethodFamily::embedded_runge_kutta)) {
    const ButcherTableau& t = *m->tableau;
    double own = 0;
    for (int p = 1; p <= t.order; ++p) own = std::max(own, order_condition_defect(t, p));
    for (int p = 1; p <= t.embedded_order; ++p) own = std::max(own, order_condition_defect(t, p, true));
    const int s = t.stages();
    table.add_row({"`" + m->name + "`", m->title, std::to_string(s),
                   std::to_string(t.order) + ", " + std::to_string(t.embedded_order),
                   t.first_same_as_last() ? "yes" : "no", std::to_string(t.first_same_as_last() ? s - 1 : s),
                   format_number(own, 1),
                   format_number(order_condition_defect(t, t.order + 1), 2) + ", " +
                       format_number(order_condition_defect(t, t.embedded_order + 1, true), 2)});
  }
  write_table_fragment(dir + "/pairs.md", table, command);
}

// The generated conditions up to order 4 exactly as the error messages state them, and the count of trees by order.
void conditions_table(const std::string& dir, const std::string& command) {
  MarkdownTable conditions({"order", "tree", "condition"}, "rll");
  int count[max_tree_order + 1] = {};
  for (const RootedTree& t : rooted_trees()) {
    ++count[t.order];
    if (t.order <= 4) conditions.add_row({std::to_string(t.order), "`" + t.bracket + "`", "`" + t.condition + "`"});
  }
  write_table_fragment(dir + "/order_conditions.md", conditions, command);
  std::vector<std::string> header = {"order p"}, row = {"trees of order p"};
  for (int p = 1; p <= max_tree_order; ++p) header.push_back(std::to_string(p)), row.push_back(std::to_string(count[p]));
  MarkdownTable counts(header, std::string(static_cast<std::size_t>(max_tree_order) + 1, 'r'));
  counts.add_row(row);
  write_table_fragment(dir + "/tree_counts.md", counts, command);
}

}  // namespace

std::vector<std::string> experiment_outputs() {
  return {"pairs.md",         "order_conditions.md", "tree_counts.md",     "hard_case.dat",      "hard_case.md",
          "pairs.dat",        "controllers.md",      "jump_response.dat",  "jump_response.md",   "estimate_check.dat",
          "estimate_summary.dat", "estimate_check.md"};
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
  estimate_check(opt, 1e-5, quick ? 32 : 64, command);
}

}  // namespace ch08
