// The tables and sentences of Chapter 6's page, from the results of one run (see fragments.hpp). Nothing here
// measures anything: it selects, fits and formats.
#include "fragments.hpp"

#include "base/format_number.hpp"
#include "program/fragment.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <map>
#include <set>

namespace ch06 {

using namespace cloth;

namespace {

// The names the page's tables and figures use for the sweep's rows.
std::string method_title(const std::string& label) {
  static const std::map<std::string, std::string> titles = {
      {"explicit_euler", "explicit Euler"},
      {"symplectic_euler", "symplectic Euler"},
      {"heun", "Heun"},
      {"rk4", "RK4"},
      {"rule38", "3/8 rule"},
      {"implicit_euler_direct", "implicit Euler, Newton, direct"},
      {"implicit_euler_cg", "implicit Euler, Newton, CG"},
      {"implicit_euler_1newton_direct", "implicit Euler, 1 iteration, direct"},
      {"implicit_euler_1newton_cg", "implicit Euler, 1 iteration, CG"},
      {"dopri5_adaptive", "adaptive Dormand-Prince"}};
  const auto it = titles.find(label);
  return it == titles.end() ? label : it->second;
}

// (50, 0) for the configuration K50_D0.
std::string config_title(const Config& c) { return "(" + format_number(c.K) + ", " + format_number(c.D) + ")"; }

// A number's exponent written short: "9.4e+06" as 9.4e6, "1e-04" as 1e-4.
std::string short_exponent(const std::string& text) {
  const auto e = text.find('e');
  if (e == std::string::npos) return text;
  const bool negative = text[e + 1] == '-';
  return text.substr(0, e + 1) + (negative ? "-" : "") + text.substr(text.find_first_not_of("+-0", e + 1));
}
// %g with `digits` significant digits: 0.12, 1e-4, 9.4e6.
std::string g(double x, int digits = 2) { return short_exponent(format_number(x, digits)); }
// Always in exponent form, for numbers far from one: 9.0e-4 rather than 0.0009.
std::string sci(double x, int digits = 2) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*e", digits - 1, x);
  return short_exponent(buffer);
}
// A quantity of a hundred or more without a fractional part, below it with `digits` significant digits.
std::string whole_or(double x, int digits) { return x >= 100 ? std::to_string(std::llround(x)) : g(x, digits); }
std::string ms(double seconds) { return whole_or(1e3 * seconds, 2) + " ms"; }
std::string us(double microseconds) { return whole_or(microseconds, 3); }
// A required error: 1e-4 m.
std::string power_of_ten(double x) { return "1e" + std::to_string(std::lround(std::log10(x))); }
// A step T / 2^k as the page writes it: 1/64 s for T = 0.25 s and k = 4.
std::string step(double h) { return "1/" + std::to_string(std::llround(1 / h)); }

const Benchmark* find(const std::vector<Benchmark>& bench, const std::string& name) {
  for (const Benchmark& b : bench)
    if (b.name == name) return &b;
  return nullptr;
}

std::string count_text(const Benchmark& b) {
  if (b.count_name.empty() || b.count == 0) return "";
  static const std::map<std::string, std::string> units = {{"multiply_adds", "multiply-adds"},
                                                           {"cg_iterations_per_solve", "CG iterations per solve"},
                                                           {"rhs_evaluations", "force evaluations"},
                                                           {"iterations", "CG iterations"}};
  const auto found = units.find(b.count_name);
  std::string unit = found == units.end() ? b.count_name : found->second;
  if (b.count == 1 && unit.back() == 's') unit.pop_back();  // 1 force evaluation
  return (b.count >= 1e5 ? g(b.count, 3) : g(b.count, 6)) + " " + unit;
}

// The least-squares slope of log y against log x.
double log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// The fastest run of the sweep on `config` whose error at T is at most `error`; nullptr when none reaches it.
const WorkPoint* fastest(const std::vector<WorkPoint>& work, const std::string& config, double error) {
  const WorkPoint* best = nullptr;
  for (const WorkPoint& p : work)
    if (!p.dropped && p.config == config && p.error <= error && (!best || p.seconds < best->seconds)) best = &p;
  return best;
}

// What distinguishes a run of the sweep from its method's others: its step, or the adaptive pair's tolerance.
std::string setting(const WorkPoint& p) {
  return p.method == "dopri5_adaptive" ? "tolerance " + power_of_ten(p.tolerance) : "h = " + step(p.h) + " s";
}

std::string run_text(const WorkPoint& p) { return method_title(p.method) + ", " + setting(p) + ", " + ms(p.seconds); }

const std::vector<double> required_errors = {1e-1, 1e-2, 1e-4, 1e-6};

void write_fastest(const std::string& dir, const std::vector<WorkPoint>& work, const std::vector<Config>& configs,
                   const std::string& command) {
  std::vector<std::string> header = {"error [m]"};
  for (const Config& c : configs) header.push_back(config_title(c));
  MarkdownTable table(header);
  // What the sentence under the table says: the fastest methods by required error, and how the adaptive pair fared.
  std::vector<std::string> winners_by_error;
  int adaptive_wins = 0;
  double adaptive_best_ratio = 1e300, adaptive_worst_ratio = 0;
  int cells = 0;
  for (const double e : required_errors) {
    std::vector<std::string> row = {power_of_ten(e)};
    std::vector<std::pair<std::string, std::string>> cell_winners;  // method, configuration
    std::set<std::string> winners;
    for (const Config& c : configs) {
      const WorkPoint* best = fastest(work, c.name, e);
      row.push_back(best ? run_text(*best) : "none reached it");
      if (!best) continue;
      ++cells;
      winners.insert(method_title(best->method));
      cell_winners.emplace_back(method_title(best->method), config_title(c));
      const WorkPoint* adaptive = nullptr;
      for (const WorkPoint& p : work)
        if (!p.dropped && p.config == c.name && p.method == "dopri5_adaptive" && p.error <= e &&
            (!adaptive || p.seconds < adaptive->seconds))
          adaptive = &p;
      if (best->method == "dopri5_adaptive")
        ++adaptive_wins;
      else if (adaptive) {
        adaptive_best_ratio = std::min(adaptive_best_ratio, adaptive->seconds / best->seconds);
        adaptive_worst_ratio = std::max(adaptive_worst_ratio, adaptive->seconds / best->seconds);
      }
    }
    table.add_row(row);
    // "to 1e-1 m, symplectic Euler on every cloth" or "to 1e-2 m, Heun on (50, 0), RK4 on (200, 20) and ...".
    if (cell_winners.empty()) continue;
    std::string text = "to " + power_of_ten(e) + (winners_by_error.empty() ? " m was " : " m, ");
    if (winners.size() == 1 && cell_winners.size() == configs.size())
      text += *winners.begin() + " on every cloth";
    else
      for (std::size_t i = 0; i < cell_winners.size(); ++i)
        text += (i == 0 ? "" : i + 1 == cell_winners.size() ? " and " : ", ") + cell_winners[i].first + " on " +
                cell_winners[i].second;
    winners_by_error.push_back(text);
  }
  write_table_fragment(dir + "/fastest.md", table, command);
  std::string sentence = "In this run the fastest way ";
  for (std::size_t i = 0; i < winners_by_error.size(); ++i)
    sentence += (i == 0 ? "" : i + 1 == winners_by_error.size() ? "; and " : "; ") + winners_by_error[i];
  sentence += ". Chapter 8's adaptive Dormand-Prince pair is the fastest in " +
              (adaptive_wins == 0 ? std::string("none") : std::to_string(adaptive_wins)) + " of the " +
              std::to_string(cells) + " cells";
  if (adaptive_worst_ratio > 0)
    sentence += "; where a fixed step wins, the adaptive pair takes " + g(adaptive_best_ratio) + " to " +
                g(adaptive_worst_ratio) + " times the winner's time";
  sentence += ".\n";
  write_text_fragment(dir + "/fastest_summary.md", sentence);
}

}  // namespace

std::vector<std::string> benchmark_fragment_names() {
  return {"benchmarks.md", "factorizations.md", "factorization_speedup.md"};
}

std::vector<std::string> study_fragment_names() {
  return {"near_zero.md", "local_error.md",      "jumps.md",   "observed_orders.md",    "sensitivity.md",
          "reference.md", "fastest.md",          "fastest_summary.md", "dropped.md", "effective_orders.md",
          "implicit_variants.md", "stiff_pick.md", "scaling.md"};
}

void write_benchmark_fragments(const std::string& dir, const std::vector<Benchmark>& bench,
                               const std::string& command) {
  MarkdownTable core({"quantity", "thread CPU [us]", "count"}, "lrr");
  for (const auto& [name, title] : std::vector<std::pair<std::string, std::string>>{
           {"force_evaluation", "one force evaluation"},
           {"newton_matrix_refill_symmetric", "Newton matrix refill (symmetric)"},
           {"factorize_block_ldlt_amd", "numeric factorization, direct path (block LDL^T)"},
           {"pcg_block_jacobi_warm_1e-8", "one CG solve to 1e-8, block-Jacobi, warm-started"},
           {"newton_iteration_ldlt", "one Newton iteration, direct"},
           {"newton_iteration_cg_warm", "one Newton iteration, warm-started CG"},
           {"rk4_step_tableau", "one RK4 step, tableau engine"},
           {"rk4_step_hand_unrolled", "one RK4 step, hand-unrolled"},
           {"explicit_euler_step", "one explicit Euler step, tableau engine"},
           {"explicit_euler_step_hand_written", "one explicit Euler step, written out"}})
    if (const Benchmark* b = find(bench, name)) core.add_row({title, us(b->cpu_microseconds), count_text(*b)});
  write_table_fragment(dir + "/benchmarks.md", core, command);

  const Benchmark* block = find(bench, "factorize_block_ldlt_amd");
  const Benchmark* ldu = find(bench, "factorize_block_ldu_amd");
  MarkdownTable factorizations({"factorization", "multiply-adds", "nonzeros of L", "thread CPU [us]",
                                "time / block LDL^T"},
                               "lrrrr");
  const Benchmark* best_scalar = nullptr;
  for (const auto& [name, title] : std::vector<std::pair<std::string, std::string>>{
           {"factorize_block_ldlt_amd", "block LDL^T, AMD on the particle graph (cloth::BlockLDU)"},
           {"factorize_block_ldu_amd", "block LDU, the same, general mode"},
           {"factorize_eigen_ldlt_amd", "Eigen SimplicialLDLT, AMD"},
           {"factorize_eigen_llt_amd", "Eigen SimplicialLLT, AMD"},
           {"factorize_eigen_ldlt_natural", "Eigen SimplicialLDLT, no ordering"},
           {"factorize_eigen_sparselu_colamd", "Eigen SparseLU, COLAMD (partial pivoting)"},
           {"factorize_cholmod_supernodal_amd", "CHOLMOD supernodal LL^T, AMD"},
           {"factorize_cholmod_supernodal_metis", "CHOLMOD supernodal LL^T, METIS"},
           {"factorize_cholmod_simplicial_amd", "CHOLMOD simplicial LDL^T, AMD"},
           {"factorize_cholmod_simplicial_metis", "CHOLMOD simplicial LDL^T, METIS"}}) {
    const Benchmark* b = find(bench, name);
    if (!b || !block) continue;
    const bool flops = b->count_name == "multiply_adds", nonzeros = b->count_name == "factor_nonzeros";
    factorizations.add_row({title, flops ? g(b->count, 3) : "", nonzeros ? g(b->count, 6) : "",
                            us(b->cpu_microseconds), g(b->cpu_microseconds / block->cpu_microseconds, 2)});
    const bool scalar = name.find("block") == std::string::npos && name.find("sparselu") == std::string::npos;
    if (scalar && (!best_scalar || b->cpu_microseconds < best_scalar->cpu_microseconds)) best_scalar = b;
  }
  write_table_fragment(dir + "/factorizations.md", factorizations, command);

  const Benchmark* lu = find(bench, "factorize_eigen_sparselu_colamd");
  std::string speedup;
  if (block && ldu && lu && best_scalar)
    speedup = "In this run the block LDL^T factorization is " +
              g(best_scalar->cpu_microseconds / block->cpu_microseconds) +
              " times faster than the fastest scalar factorization of the same matrix and sustains " +
              g(1e-3 * block->count / block->cpu_microseconds) +
              " billion multiply-adds per second; the block LDU for a non-symmetric matrix is " +
              g(lu->cpu_microseconds / ldu->cpu_microseconds) + " times faster than Eigen's SparseLU.\n";
  write_text_fragment(dir + "/factorization_speedup.md", speedup);
}

void write_study_fragments(const std::string& dir, const StudyResults& r, const std::vector<Config>& configs,
                           const std::string& command) {
  // Where and when the shortest spring comes near zero length.
  {
    const NearZero& nz = r.near_zero;
    const auto first_below = [&](double level) {
      for (std::size_t i = 0; i < nz.t.size(); ++i)
        if (nz.shortest[i] < level) return g(nz.t[i], 3) + " s";
      return std::string("never");
    };
    int dips = 0;
    for (std::size_t i = 1; i < nz.t.size(); ++i)
      if (nz.shortest[i] < 1e-2 && nz.shortest[i - 1] >= 1e-2) ++dips;
    write_text_fragment(dir + "/near_zero.md",
                        "In this run (RK4, h = " + g(nz.h) +
                            " s) the shortest spring first falls below 0.5 L0 at t = " +
                            first_below(0.5) + " and below 0.1 L0 at t = " + first_below(0.1) +
                            "; it is shortest, " + sci(nz.smallest) + " L0, at t = " + g(nz.t_smallest, 3) + " s (" +
                            nz.spring + "), and dips below 0.01 L0 " + std::to_string(dips) + " times before t = " +
                            g(nz.t.back()) + " s.\n");
  }
  // RK4's local error along the trajectory, and the jumps.
  {
    MarkdownTable jumps({"h [s]", "steps with a jump", "velocity error [m/s]", "16/15 J h / 4",
                         "position error [m]", "16/15 J h^2 / 6"},
                        "rrrrrr");
    for (const LocalError& e : r.local_errors)
      jumps.add_row({g(e.h), std::to_string(e.jump_steps) + " of " + std::to_string(e.steps), g(e.worst_velocity, 4),
                     g(16.0 / 15.0 * e.jump * e.h / 4, 4), g(e.worst_position, 4),
                     g(16.0 / 15.0 * e.jump * e.h * e.h / 6, 4)});
    write_table_fragment(dir + "/jumps.md", jumps, command);
    std::string sentence;
    for (const LocalError& e : r.local_errors)
      if (std::abs(e.h - 1e-3) < 1e-12)
        sentence = "With h = 1e-3 s, a step without a jump makes a local error of about " + g(e.smooth_median) +
                   " m (the median over the run); " + std::to_string(e.jump_steps) + " of the " +
                   std::to_string(e.steps) + " steps are different: their errors reach " + g(e.worst_position) +
                   " m, " + sci(e.worst_position / e.smooth_median, 1) + " times more.\n";
    write_text_fragment(dir + "/local_error.md", sentence);
  }
  // Observed orders from successive halvings: one row per method and horizon, one column per step.
  {
    std::vector<long long> divisions;  // h = T / division
    for (const ObservedOrder& o : r.orders) {
      const long long d = std::llround(o.T / o.h);
      if (std::find(divisions.begin(), divisions.end(), d) == divisions.end()) divisions.push_back(d);
    }
    std::sort(divisions.begin(), divisions.end());
    std::vector<std::string> header = {"method", "T [s]", "difference at h = T/" + std::to_string(divisions.front())};
    for (std::size_t i = 1; i < divisions.size(); ++i) header.push_back("order at T/" + std::to_string(divisions[i]));
    header.push_back("difference at T/" + std::to_string(divisions.back()));
    MarkdownTable table(header, "l" + std::string(header.size() - 1, 'r'));
    std::vector<std::pair<std::string, double>> rows;
    for (const ObservedOrder& o : r.orders)
      if (std::find(rows.begin(), rows.end(), std::make_pair(o.method, o.T)) == rows.end())
        rows.emplace_back(o.method, o.T);
    for (const auto& [method, T] : rows) {
      std::vector<std::string> row = {method_title(method), g(T), "-"};
      std::vector<std::string> orders(divisions.size() - 1, "-");
      std::string last = "-";
      for (const ObservedOrder& o : r.orders) {
        if (o.method != method || o.T != T) continue;
        const auto at = std::find(divisions.begin(), divisions.end(), std::llround(o.T / o.h)) - divisions.begin();
        if (at == 0) row[2] = g(o.difference);
        if (at > 0 && !std::isnan(o.order)) orders[static_cast<std::size_t>(at - 1)] = format_fixed(o.order, 2);
        if (at + 1 == static_cast<long>(divisions.size())) last = g(o.difference);
      }
      row.insert(row.end(), orders.begin(), orders.end());
      row.push_back(last);
      table.add_row(row);
    }
    write_table_fragment(dir + "/observed_orders.md", table, command);
  }
  // How much each configuration amplifies a perturbation.
  {
    MarkdownTable table({"(K, D)", "largest for t <= 0.25 s", "largest for t <= 0.5 s", "at t = 1 s",
                         "first above 100 at", "first above 1e6 at"},
                        "lrrrrr");
    for (std::size_t c = 0; c < r.sensitivity.size() && c < configs.size(); ++c) {
      const Sensitivity& s = r.sensitivity[c];
      double up_to_quarter = 0, up_to_half = 0;
      std::string above_100 = "never", above_million = "never";
      for (std::size_t i = 0; i < s.t.size(); ++i) {
        if (s.t[i] <= 0.25 + 1e-12) up_to_quarter = std::max(up_to_quarter, s.amplification[i]);
        if (s.t[i] <= 0.5 + 1e-12) up_to_half = std::max(up_to_half, s.amplification[i]);
        if (above_100 == "never" && s.amplification[i] > 100) above_100 = "t = " + g(s.t[i], 3) + " s";
        if (above_million == "never" && s.amplification[i] > 1e6) above_million = "t = " + g(s.t[i], 3) + " s";
      }
      const auto amplification = [](double a) { return a < 1e4 ? whole_or(a, 2) : g(a, 2); };
      table.add_row({config_title(configs[c]), amplification(up_to_quarter), amplification(up_to_half),
                     amplification(s.amplification.back()), above_100, above_million});
    }
    write_table_fragment(dir + "/sensitivity.md", table, command);
  }
  // The reference's credentials.
  {
    MarkdownTable table({"(K, D)", "RK4 steps", "3/8-rule steps", "largest sampled difference [m]",
                         "smallest error plotted [m]"},
                        "lrrrr");
    for (std::size_t c = 0; c < r.references.size() && c < configs.size(); ++c) {
      const ReferenceCheck& ref = r.references[c];
      table.add_row({config_title(configs[c]), std::to_string(ref.steps), std::to_string(2 * ref.steps),
                     g(ref.agreement), g(100 * ref.agreement)});
    }
    write_table_fragment(dir + "/reference.md", table, command);
  }
  write_fastest(dir, r.work, configs, command);
  // The runs left out of the diagrams, and why.
  {
    MarkdownTable table({"(K, D)", "method", "h or tolerance", "why"});
    for (const Config& c : configs)
      for (const WorkPoint& p : r.work) {
        if (!p.dropped || p.config != c.name) continue;
        const std::string why = p.why == "below_100x_reference_agreement"
                                    ? "error " + g(p.error) + " m, within 100 times the reference's uncertainty"
                                    : p.why;
        table.add_row({config_title(c), method_title(p.method), setting(p), why});
      }
    write_table_fragment(dir + "/dropped.md", table, command);
  }
  // Effective orders: the slope of log error against log h over each method's surviving fixed steps.
  {
    std::vector<std::string> header = {"method"};
    for (const Config& c : configs) header.push_back(config_title(c));
    MarkdownTable table(header, "l" + std::string(configs.size(), 'r'));
    for (const SweepMethod& m : sweep_methods()) {
      std::vector<std::string> row = {method_title(m.label)};
      for (const Config& c : configs) {
        std::vector<double> h, error;
        for (const WorkPoint& p : r.work)
          if (!p.dropped && p.config == c.name && p.method == m.label) h.push_back(p.h), error.push_back(p.error);
        const std::string points = " (" + std::to_string(h.size()) + ")";
        row.push_back(h.size() < 2 ? "-" : format_fixed(log_slope(h, error), 2) + points);
      }
      table.add_row(row);
    }
    write_table_fragment(dir + "/effective_orders.md", table, command);
  }
  // The four implicit variants at the largest step on the first configuration.
  {
    MarkdownTable table({"variant", "error at T [m]", "time", "Newton iterations", "factorizations",
                         "CG iterations"},
                        "lrrrrr");
    const Config& c = configs.front();
    double largest = 0;
    for (const WorkPoint& p : r.work)
      if (p.config == c.name && p.method != "dopri5_adaptive") largest = std::max(largest, p.h);
    for (const SweepMethod& m : sweep_methods()) {
      if (m.method != "implicit_euler") continue;
      for (const WorkPoint& p : r.work)
        if (!p.dropped && p.config == c.name && p.method == m.label && p.h == largest)
          table.add_row({method_title(m.label), g(p.error), ms(p.seconds), std::to_string(p.counters.newton_iterations),
                         std::to_string(p.counters.factorizations), std::to_string(p.counters.cg_iterations)});
    }
    write_table_fragment(dir + "/implicit_variants.md", table, command);
  }
  // On the stiff cloth: the most accurate RK4 run against the most accurate implicit Euler run.
  {
    const Config& stiff = configs.back();
    const WorkPoint *rk4 = nullptr, *implicit = nullptr;
    for (const WorkPoint& p : r.work) {
      if (p.dropped || p.config != stiff.name) continue;
      if (p.method == "rk4" && (!rk4 || p.error < rk4->error)) rk4 = &p;
      if (p.method.rfind("implicit_euler", 0) == 0 && (!implicit || p.error < implicit->error)) implicit = &p;
    }
    std::string sentence;
    if (rk4 && implicit)
      sentence = "On the stiff cloth " + config_title(stiff) + ", RK4's most accurate run of this sweep reaches " +
                 g(rk4->error) + " m in " + ms(rk4->seconds) + " (h = " + step(rk4->h) +
                 " s); the most accurate implicit Euler run (" + method_title(implicit->method) + ", h = " +
                 step(implicit->h) + " s) is " + g(implicit->error) + " m off after " + ms(implicit->seconds) + ".\n";
    write_text_fragment(dir + "/stiff_pick.md", sentence);
  }
  // The cost of a step against the grid.
  {
    std::vector<int> sizes;
    std::map<int, int> springs;
    for (const ScalingPoint& p : r.scaling) {
      if (std::find(sizes.begin(), sizes.end(), p.size) == sizes.end()) sizes.push_back(p.size);
      springs[p.size] = p.springs;
    }
    std::sort(sizes.begin(), sizes.end());
    // An exponent is fitted only over three sizes or more: two points always lie on a line.
    bool fit = false;
    for (const char* m : {"explicit_euler", "rk4", "implicit_euler_direct", "implicit_euler_cg"}) {
      long n = std::count_if(r.scaling.begin(), r.scaling.end(), [&](const ScalingPoint& p) { return p.method == m; });
      fit = fit || n >= 3;
    }
    std::vector<std::string> header = {"per step"};
    for (const int s : sizes)
      header.push_back(std::to_string(s) + " x " + std::to_string(s) + " (" + std::to_string(springs[s]) + " springs)");
    if (fit) header.push_back("exponent");
    MarkdownTable table(header, "l" + std::string(header.size() - 1, 'r'));
    const auto row = [&](const std::string& title, const std::string& method, auto cell, bool with_exponent) {
      std::vector<std::string> cells = {title};
      std::vector<double> x, y;
      for (const int s : sizes) {
        const auto it = std::find_if(r.scaling.begin(), r.scaling.end(),
                                     [&](const ScalingPoint& p) { return p.method == method && p.size == s; });
        cells.push_back(it == r.scaling.end() ? "(not run)" : cell(*it));
        if (it != r.scaling.end()) x.push_back(it->springs), y.push_back(it->cpu_per_step);
      }
      if (fit) cells.push_back(with_exponent && x.size() >= 3 ? format_fixed(log_slope(x, y), 2) : "");
      table.add_row(cells);
    };
    const auto time = [](const ScalingPoint& p) { return ms(p.cpu_per_step); };
    row("explicit Euler", "explicit_euler", time, true);
    row("RK4", "rk4", time, true);
    row("implicit Euler, direct", "implicit_euler_direct", time, true);
    row("of which factorization", "implicit_euler_direct",
        [](const ScalingPoint& p) {
          return std::to_string(std::lround(100 * p.factorization_per_step / p.mean_wall_per_step)) + " %";
        }, false);
    row("implicit Euler, CG", "implicit_euler_cg", time, true);
    row("Newton iterations per step", "implicit_euler_cg",
        [](const ScalingPoint& p) { return g(p.newton_per_step); }, false);
    row("CG iterations per solve", "implicit_euler_cg", [](const ScalingPoint& p) { return g(p.cg_per_solve); }, false);
    write_table_fragment(dir + "/scaling.md", table, command);
  }
}

}  // namespace ch06
