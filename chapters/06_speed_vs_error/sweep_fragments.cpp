// What Chapter 6's work-precision sweep found, as the page quotes it (see sweep.hpp): the reference's
// credentials, the cheapest run for each required error with its counts and its timing's spread, the runs left
// out, the effective orders, the implicit variants and the stiff cloth's pick. Nothing here measures anything.
#include "page_text.hpp"
#include "sweep.hpp"

#include "program/fragment.hpp"

#include <algorithm>
#include <set>

namespace ch06 {

using namespace cloth;

namespace {

const std::vector<double> required_errors = {1e-1, 1e-2, 1e-4, 1e-6};

// The fastest run of `method` (any method when empty) on `config` whose error at T is at most `error`.
const WorkPoint* fastest(const std::vector<WorkPoint>& work, const std::string& config, double error,
                         const std::string& method = "") {
  const WorkPoint* best = nullptr;
  for (const WorkPoint& p : work)
    if (!p.dropped && p.config == config && p.error <= error && (method.empty() || p.method == method) &&
        (!best || p.timing.fastest_cpu < best->timing.fastest_cpu))
      best = &p;
  return best;
}

// What distinguishes a run of the sweep from its method's others: its step, or the adaptive pair's tolerance.
std::string setting(const WorkPoint& p) {
  return p.method == "dopri5" ? "tolerance " + power_of_ten(p.tolerance) : "h = " + step_text(p.h) + " s";
}

// The work a run did, in counts that do not depend on the machine: force evaluations, and for the implicit
// methods the factorizations or CG iterations of their Newton iterations.
std::string counts(const WorkPoint& p) {
  std::string text = std::to_string(p.counters.rhs_evaluations) + " force evaluations";
  if (p.counters.factorizations > 0) text += ", " + std::to_string(p.counters.factorizations) + " factorizations";
  if (p.counters.cg_iterations > 0) text += ", " + std::to_string(p.counters.cg_iterations) + " CG iterations";
  return text;
}

// A run of implicit Euler with any Newton settings: its composed name's method is the registry's implicit_euler.
bool is_implicit_euler(const WorkPoint& p) { return parse_configuration(p.method).method == "implicit_euler"; }

std::string run_text(const WorkPoint& p) {
  return method_title(p.method) + ", " + setting(p) + ": " + counts(p) + "; " +
         ms_with_spread(p.timing.fastest_cpu, p.timing.slowest_cpu);
}

void write_fastest(const std::string& dir, const std::vector<WorkPoint>& work, const std::vector<Config>& configs,
                   const std::string& command) {
  std::vector<std::string> header = {"error [m]"};
  for (const Config& c : configs) header.push_back(config_title(c));
  MarkdownTable table(header);
  int adaptive_wins = 0, cells = 0;
  double adaptive_best_ratio = 1e300, adaptive_worst_ratio = 0;
  std::set<std::string> winners;
  for (const double e : required_errors) {
    std::vector<std::string> row = {power_of_ten(e)};
    for (const Config& c : configs) {
      const WorkPoint* best = fastest(work, c.name, e);
      row.push_back(best ? run_text(*best) : "none reached it");
      if (!best) continue;
      ++cells;
      winners.insert(method_title(best->method));
      const WorkPoint* adaptive = fastest(work, c.name, e, "dopri5");
      if (best->method == "dopri5") {
        ++adaptive_wins;
      } else if (adaptive) {
        const double ratio = adaptive->timing.fastest_cpu / best->timing.fastest_cpu;
        adaptive_best_ratio = std::min(adaptive_best_ratio, ratio);
        adaptive_worst_ratio = std::max(adaptive_worst_ratio, ratio);
      }
    }
    table.add_row(row);
  }
  write_table_fragment(dir + "/fastest.md", table, command);
  std::string sentence = "In this run " + std::to_string(winners.size()) + " different methods are the cheapest in " +
                         std::to_string(cells) + " cells. Chapter 8's adaptive Dormand-Prince pair is the cheapest in " +
                         (adaptive_wins == 0 ? std::string("none") : std::to_string(adaptive_wins)) + " of them";
  if (adaptive_worst_ratio > 0)
    sentence += "; where a fixed step wins, the adaptive pair takes " + g(adaptive_best_ratio) + " to " +
                g(adaptive_worst_ratio) + " times the winner's time";
  write_text_fragment(dir + "/fastest_summary.md", sentence + ".\n");
}

void write_references(const std::string& dir, const std::vector<ReferenceCheck>& references,
                      const std::vector<Config>& configs, const std::string& command) {
  MarkdownTable table({"(K, D)", "RK4 steps", "3/8-rule steps", "largest sampled difference [m]",
                       "smallest error plotted [m]"},
                      "lrrrr");
  for (std::size_t c = 0; c < references.size() && c < configs.size(); ++c) {
    const ReferenceCheck& ref = references[c];
    table.add_row({config_title(configs[c]), std::to_string(ref.steps), std::to_string(2 * ref.steps),
                   g(ref.agreement), g(100 * ref.agreement)});
  }
  write_table_fragment(dir + "/reference.md", table, command);
}

void write_dropped(const std::string& dir, const std::vector<WorkPoint>& work, const std::vector<Config>& configs,
                   const std::string& command) {
  MarkdownTable table({"(K, D)", "method", "h or tolerance", "why"});
  for (const Config& c : configs)
    for (const WorkPoint& p : work) {
      if (!p.dropped || p.config != c.name) continue;
      const std::string why = p.why == "below_100x_reference_agreement"
                                  ? "error " + g(p.error) + " m, within 100 times the reference's uncertainty"
                                  : p.why;
      table.add_row({config_title(c), method_title(p.method), setting(p), why});
    }
  write_table_fragment(dir + "/dropped.md", table, command);
}

// Effective orders: the slope of log error against log h over each method's surviving fixed steps.
void write_effective_orders(const std::string& dir, const std::vector<WorkPoint>& work,
                            const std::vector<Config>& configs, const std::string& command) {
  std::vector<std::string> header = {"method"};
  for (const Config& c : configs) header.push_back(config_title(c));
  MarkdownTable table(header, std::string("l").append(configs.size(), 'r'));
  for (const std::string& method : sweep_methods()) {
    if (method == "dopri5") continue;
    std::vector<std::string> row = {method_title(method)};
    for (const Config& c : configs) {
      std::vector<double> h, error;
      for (const WorkPoint& p : work)
        if (!p.dropped && p.config == c.name && p.method == method) h.push_back(p.h), error.push_back(p.error);
      row.push_back(h.size() < 2 ? "-" : format_fixed(log_slope(h, error), 2) + " (" + std::to_string(h.size()) + ")");
    }
    table.add_row(row);
  }
  write_table_fragment(dir + "/effective_orders.md", table, command);
}

// The four implicit variants at the largest step on the first configuration, and the stiff cloth's most accurate
// RK4 run against its most accurate implicit Euler run.
void write_implicit(const std::string& dir, const std::vector<WorkPoint>& work, const std::vector<Config>& configs,
                    const std::string& command) {
  MarkdownTable table({"variant", "error at T [m]", "CPU time (spread)", "Newton iterations", "factorizations",
                       "CG iterations"},
                      "lrrrrr");
  double largest = 0;
  for (const WorkPoint& p : work)
    if (p.config == configs.front().name && p.method != "dopri5") largest = std::max(largest, p.h);
  for (const WorkPoint& p : work)
    if (!p.dropped && p.config == configs.front().name && is_implicit_euler(p) && p.h == largest)
      table.add_row({method_title(p.method), g(p.error), ms_with_spread(p.timing.fastest_cpu, p.timing.slowest_cpu),
                     std::to_string(p.counters.newton_iterations), std::to_string(p.counters.factorizations),
                     std::to_string(p.counters.cg_iterations)});
  write_table_fragment(dir + "/implicit_variants.md", table, command);

  const Config& stiff = configs.back();
  const WorkPoint *rk4 = nullptr, *implicit = nullptr;
  for (const WorkPoint& p : work) {
    if (p.dropped || p.config != stiff.name) continue;
    if (p.method == "rk4" && (!rk4 || p.error < rk4->error)) rk4 = &p;
    if (is_implicit_euler(p) && (!implicit || p.error < implicit->error)) implicit = &p;
  }
  std::string sentence;
  if (rk4 && implicit)
    sentence = "On the stiff cloth " + config_title(stiff) + ", RK4's most accurate run of this sweep reaches " +
               g(rk4->error) + " m with " + counts(*rk4) + " in " + ms(rk4->timing.fastest_cpu) + " (h = " +
               step_text(rk4->h) + " s); the most accurate implicit Euler run (" + method_title(implicit->method) +
               ", h = " + step_text(implicit->h) + " s) is " + g(implicit->error) + " m off after " +
               counts(*implicit) + " and " + ms(implicit->timing.fastest_cpu) + ".\n";
  write_text_fragment(dir + "/stiff_pick.md", sentence);
}

}  // namespace

void write_sweep_fragments(const std::string& dir, const std::vector<ReferenceCheck>& references,
                           const std::vector<WorkPoint>& work, const std::vector<Config>& configs,
                           const std::string& command) {
  write_references(dir, references, configs, command);
  write_fastest(dir, work, configs, command);
  write_dropped(dir, work, configs, command);
  write_effective_orders(dir, work, configs, command);
  write_implicit(dir, work, configs, command);
}

}  // namespace ch06
