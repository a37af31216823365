// Chapter 8's tables of the pairs themselves, from their tableaus alone: the registry's pairs with the residuals of
// their order conditions, the conditions the rooted trees generate, and each pair's response to a jump in the
// acceleration inside a step (what its stages see and what its estimate reports).
#include "experiments.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/order_conditions.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ch08 {

using namespace cloth;

namespace {

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

}  // namespace

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

}  // namespace ch08
