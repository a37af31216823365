// Chapter 10's map of the cheapest method over resolution and stiffness, from a cost model: each method's cost
// per step measured against the grid, and its cheapest run on the 20 x 20 fabric (error_curves.cpp) scaled to
// finer grids. A level the rest state already meets is printed as met by standing still, never as a win.
#include "real_cloth.hpp"

#include "analysis/lattice_frequency.hpp"
#include "analysis/trajectory_measures.hpp"
#include "integrators/configuration.hpp"
#include "program/fragment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace cloth;

namespace ch10 {

namespace {

// [step_cost]
// CPU seconds per step on the n x n fabric (K = 1e5, from rest; steps of 1/60 s for implicit methods, 1e-6 s for
// explicit ones, inside their stability limit at every size), the best of three runs.
double measure_step_cost(int n, const std::string& method, int steps) {
  const Scene scene(fabric(n, 1e5));
  const double h = is_explicit(method) ? 1e-6 : 1.0 / 60;
  double best = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const Run r = run_to(scene, method, steps * h, steps, 0);
    best = std::min(best, r.seconds / static_cast<double>(steps));
  }
  return best;
}
// [step_cost]

// The method whose measured step cost stands for `method`'s growth with the grid: full Newton costs what its
// iterations cost, one iteration's cost grows like a single-iteration step's, and every local/global iteration
// count grows like 10 iterations.
std::string cost_proxy(const std::string& method) {
  if (method == "implicit_euler/exact") return "implicit_euler/one/exact";
  if (method == "implicit_euler/cg") return "implicit_euler/one/cg";
  if (parse_configuration(method).method == "local_global") return "local_global";
  return method;
}

struct SizeCost {
  double seconds = 0;
  bool measured = false;
};

const std::vector<int> sizes = {20, 39, 77, 153};  // particles per side

double springs(int n) {
  double total = 0;
  for (SpringFamily f : all_spring_families) total += spring_count(f, n, n);
  return total;
}

using StepCosts = std::map<std::string, std::map<int, SizeCost>>;

// 1. Cost per step against the grid: measured where affordable, beyond that extrapolated as a power of the number
//    of springs fitted to the two largest measured sizes (step_cost.md, step_cost.dat).
StepCosts step_costs(const Settings& s) {
  StepCosts cost;
  std::vector<std::string> header = {"method"};
  for (int n : sizes) header.push_back(format("%d x %d", n, n));
  header.emplace_back("exponent");
  MarkdownTable cost_md(header, "lrrrrr");
  std::string cost_dat = "# method n springs seconds_per_step measured\n";
  for (const char* name :
       {"symplectic_euler", "rk4", "implicit_euler/one/exact", "implicit_euler/one/cg", "local_global"}) {
    const std::string method = name;
    const bool direct = method == "implicit_euler/one/exact";
    std::vector<int> measured;
    for (int n : sizes) {
      // The quick run measures up to 77 x 77 (39 x 39 for the direct solve, whose factorization is the slowest).
      if (n > (s.quick ? (direct ? 39 : 77) : (direct ? 77 : 153))) continue;
      const int steps = is_explicit(method) ? (n > 40 ? 20 : 200) : (n > 40 ? 2 : 10);
      cost[method][n] = {measure_step_cost(n, method, steps), true};
      measured.push_back(n);
    }
    const int a = measured[measured.size() - 2], b = measured.back();
    const double exponent =
        std::log(cost[method][b].seconds / cost[method][a].seconds) / std::log(springs(b) / springs(a));
    for (int n : sizes)
      if (!cost[method][n].measured)
        cost[method][n] = {cost[method][b].seconds * std::pow(springs(n) / springs(b), exponent), false};
    std::vector<std::string> row = {label(method)};
    for (int n : sizes) {
      row.push_back(
          format("%.3g ms%s", 1e3 * cost[method][n].seconds, cost[method][n].measured ? "" : " (predicted)"));
      cost_dat += format("%s %d %.0f %.6e %d\n", method.c_str(), n, springs(n), cost[method][n].seconds,
                         cost[method][n].measured ? 1 : 0);
    }
    row.push_back(format("%.2f", exponent));
    cost_md.add_row(row);
    cost_dat += "\n\n";
    std::printf("cost per step %s: exponent %.2f over %d..%d\n", method.c_str(), exponent, a, b);
  }
  write_table_fragment(s.out + "/step_cost.md", cost_md, s.command);
  write_text(s.out, "step_cost.dat", cost_dat);
  return cost;
}

// 2. The map of the cheapest method at each grid and K, predicted from the 20 x 20 runs (map_1cm.md, map_1mm.md,
//    map.dat, map_winners.dat).
void predicted_map(const Settings& s, const StepCosts& cost, const std::map<double, Curves>& curves,
                   const std::vector<std::string>& methods) {
  // [cost_model]
  // cost[method][n]: the CPU seconds of one step on the n x n fabric, measured at K = 1e5 N/m (or extrapolated
  // from the two largest measured sizes: the step-cost table) and used for every K; cost_proxy(method) names the
  // method whose step stands for this one's (one Newton iteration's for full Newton's, 10 local/global
  // iterations' for any number).
  // 2. Predicted CPU time of each method on the n x n fabric of stiffness K to reach a tolerance: its cheapest run
  //    that reached it on the 20 x 20 fabric (same K), with the time per step scaled by the measured growth of a
  //    step with the grid and, for an explicit method, the number of steps scaled by omega_max(n) / omega_max(20):
  //    its stable step shrinks with the spacing. An implicit method keeps its step, because the motion of the
  //    same square metre converges as the grid is refined (the refinement study).
  const auto predicted = [&](const Measurement& m, int n, double K) {
    double steps = static_cast<double>(m.steps);
    if (is_explicit(m.method))
      steps *= lattice_fastest_frequency({K, K, K, fabric(n, K).mass}) /
               lattice_fastest_frequency({K, K, K, fabric(20, K).mass});
    const std::string proxy = cost_proxy(m.method);
    return m.seconds / static_cast<double>(m.steps) * cost.at(proxy).at(n).seconds / cost.at(proxy).at(20).seconds *
           steps;
  };
  // [cost_model]
  std::string dat = "# tol K n method predicted_cpu_seconds\n";
  // Each row states the size of the motion at T (the rest state's distance from the 20 x 20 reference; the motion
  // of the same square metre converges as the grid is refined), beside which a level is measured.
  std::vector<std::string> map_header = {"K [N/m]", "motion at T [m]"};
  for (int n : sizes) map_header.push_back(format("%d x %d", n, n));
  MarkdownTable md[2] = {MarkdownTable(map_header, "llllll"), MarkdownTable(map_header, "llllll")};
  const double tols[2] = {1e-2, 1e-3};
  int winner_index = 0;
  std::map<std::string, int> winner_code;
  std::string winners =
      "# tol K n winner_code winner predicted_seconds runner_up_ratio motion_at_T (code -1: met by standing still)\n";
  for (const auto& [K, c] : curves) {
    if (c.T != 0.5) continue;
    for (int t = 0; t < 2; ++t) {
      std::vector<std::string> row = {stiffness_text(K), format("%.3g", c.displacement)};
      const bool still = accuracy_verdict(0, c.displacement, tols[t]) == AccuracyVerdict::met_by_rest;
      for (int n : sizes) {
        if (still) {  // nobody's win: marked apart in the figure (winner code -1)
          row.emplace_back("met by standing still");
          winners += format("%g %g %d -1 standing_still 0 0 %.6e\n", tols[t], K, n, c.displacement);
          continue;
        }
        std::string best;
        double best_seconds = INFINITY, second = INFINITY;
        for (const std::string& method : methods) {
          const Measurement* m = cheapest(c, method, tols[t]);
          if (m == nullptr) continue;
          const double seconds = predicted(*m, n, K);
          dat += format("%g %g %d %s %.6e\n", tols[t], K, n, method.c_str(), seconds);
          if (seconds < best_seconds) second = best_seconds, best_seconds = seconds, best = method;
          else second = std::min(second, seconds);
        }
        if (best.empty()) {
          row.emplace_back("none reached it");
          continue;
        }
        if (!winner_code.contains(best)) winner_code[best] = winner_index++;
        winners += format("%g %g %d %d %s %.6e %.6e %.6e\n", tols[t], K, n, winner_code[best], best.c_str(),
                          best_seconds, second / best_seconds, c.displacement);
        row.push_back(format("%s: %.3g s%s, next %.1fx", label(best).c_str(), best_seconds,
                             n == 20 ? " (measured)" : "", second / best_seconds));
      }
      md[t].add_row(row);
    }
  }
  write_table_fragment(s.out + "/map_1cm.md", md[0], s.command);
  write_table_fragment(s.out + "/map_1mm.md", md[1], s.command);
  write_text(s.out, "map.dat", dat);
  write_text(s.out, "map_winners.dat", winners);
}

}  // namespace

void cost_map(const Settings& s, const std::map<double, Curves>& curves, const std::vector<std::string>& methods) {
  predicted_map(s, step_costs(s), curves, methods);
}

}  // namespace ch10
