// Chapter 10's error curves: every method at its candidate steps on the 20 x 20 fabric of stiffness K, each run's
// CPU time and its largest distance at T from a reference, the sweep the practitioner's table and the map read.
#include "real_cloth.hpp"

#include "analysis/lattice_frequency.hpp"
#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"

#include <cmath>
#include <cstdio>

using namespace cloth;

namespace ch10 {

void print_curves(const Curves& c) {
  const std::string check = c.reference_agreement < 0
                                ? "not checked against the 3/8 rule"
                                : "3/8 rule at twice as many: " + format_number(c.reference_agreement, 3) + " m";
  std::printf("K %g, T %g: reference RK4 with %lld steps (%s)\n", c.K, c.T, c.reference_steps, check.c_str());
  for (const Measurement& m : c.rows)
    std::printf("  %-20s h %-10.4g steps %-7lld %8.4f s  error %.3e %s\n", m.method.c_str(), m.h, m.steps, m.seconds,
                m.error, m.ok ? "" : m.message.c_str());
}

// [sweep]
// Every method at its candidate steps: explicit methods from 95 % of their predicted stable step downwards,
// implicit ones from one step per 1/30 s frame downwards, each halving until the error at T is below 0.5 mm, a run
// costs more than `plan.budget` CPU seconds, or `plan.max_halvings` halvings. Runs shorter than plan.budget / 4
// are repeated and timed by their fastest run (run_to).
Curves error_curves(double K, double T, const std::vector<std::string>& methods, bool check_reference,
                    const CurvePlan& plan) {
  const SceneParams p = fabric(20, K);
  const Scene scene(p);
  const double omega = lattice_fastest_frequency({K, K, K, p.mass});
  Curves c{K, T, 0, -1, 0, {}};
  // The reference: RK4 at a quarter of its stable step (a third in the quick run; RK4 at the stable step itself is
  // within ~1e-7 m of it, measured below), checked in the full run against the 3/8 rule, a different fourth-order
  // method, at half that step.
  c.reference_steps = static_cast<long long>(std::ceil(T / (2 * std::sqrt(2.0) / omega / plan.reference_division)));
  const Vector ref = reference(scene, T, c.reference_steps, check_reference, c.reference_agreement);
  c.displacement = largest_distance(ref, scene.initial_positions());
  for (const std::string& method : methods) {
    long long steps = 0;
    if (is_explicit(method)) {
      // 95 % of the predicted stable step: as large as stability allows, with a margin for the sagged state.
      steps = static_cast<long long>(std::ceil(T / (0.95 * stability_reach(method) / omega)));
    } else {
      steps = std::llround(T * 30);
    }
    for (int k = 0; k <= plan.max_halvings; ++k, steps *= 2) {
      const Run r = run_to(scene, method, T, steps, plan.budget / 4);
      Measurement m{method, T / static_cast<double>(steps), steps, r.seconds, NAN, r.ok, r.message, r.counters};
      if (r.ok) m.error = largest_distance(r.x, ref);
      c.rows.push_back(m);
      if ((r.ok && m.error < 5e-4) || r.seconds > plan.budget) break;
    }
  }
  return c;
}
// [sweep]

const Measurement* cheapest(const Curves& c, const std::string& method, double tol) {
  std::vector<const Measurement*> runs;
  std::vector<RunCost> costs;
  for (const Measurement& m : c.rows)
    if (m.method == method) runs.push_back(&m), costs.push_back({m.ok ? m.error : NAN, m.seconds});
  const int best = fastest_reaching(costs, c.displacement, tol);  // none at a level standing still meets
  return best < 0 ? nullptr : runs[static_cast<std::size_t>(best)];
}

std::string curves_tag(double K) { return format("K%g", K); }

void write_curves(const Settings& s, const Curves& c, const std::string& tag) {
  std::string dat = "# method h steps cpu_seconds error_at_T rhs factorizations linear_solves cg_iterations "
                    "newton_iterations status (one block per method)\n";
  std::string last;
  for (const Measurement& m : c.rows) {
    if (m.method != last && !last.empty()) dat += "\n\n";
    last = m.method;
    dat += format("%s %.6e %lld %.6e %.6e %lld %lld %lld %lld %lld %s\n", m.method.c_str(), m.h, m.steps, m.seconds,
                  m.error, m.counters.rhs_evaluations, m.counters.factorizations, m.counters.linear_solves,
                  m.counters.cg_iterations, m.counters.newton_iterations, m.ok ? "ok" : "failed");
  }
  write_text(s.out, "curves_" + tag + ".dat", dat);
}

}  // namespace ch10
