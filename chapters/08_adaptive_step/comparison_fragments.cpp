// What Chapter 8's comparison with Boost.Odeint found, as the page quotes it (comparison.hpp). Nothing here
// measures anything: it selects and formats. Errors below 100 times the reference's credential are left out.
#include "comparison.hpp"

#include "base/format_number.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <cstdio>
#include <functional>

namespace ch08 {

using namespace cloth;

namespace {

std::string ms(double seconds) { return std::isnan(seconds) ? std::string("-") : format_number(1e3 * seconds, 3); }
std::string ratio(double x) { return std::isnan(x) ? std::string("-") : format_fixed(x, 2); }

// [levels]
// The least CPU time (the fastest of its timed runs) of a row that `keep` accepts and whose error at T is within
// `level`; NaN when no such row reached it. `which` receives the row.
double cheapest(const std::vector<Row>& rows, double level, const std::function<bool(const Row&)>& keep,
                const Row** which = nullptr) {
  const Row* best = nullptr;
  for (const Row& r : rows)
    if (keep(r) && r.error <= level && (!best || r.timing.fastest_cpu < best->timing.fastest_cpu)) best = &r;
  if (which) *which = best;
  return best ? best->timing.fastest_cpu : std::nan("");
}
// [levels]

bool is(const Row& r, const char* series, const char* method) { return r.series == series && r.method == method; }

void write_table(const std::string& dir, const std::vector<Row>& rows, const Reference& ref, double T,
                 const SceneParams& s) {
  std::vector<Row> sorted = rows;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Row& a, const Row& b) {
    return a.series != b.series ? a.series < b.series : a.method < b.method;
  });
  OutputFile table(dir + "work_precision.dat");
  std::fprintf(table.get(), "# series method tol error_at_T_m wall_s cpu_s evaluations cpu_slowest_s  (T = %g s, K = %g, "
                            "D = %g; reference agreement %.3e m; blocks by series and method)\n",
               T, s.stiffness, s.damping, ref.agreement);
  std::string last;
  for (const Row& r : sorted) {
    const std::string key = r.series + " " + r.method;
    if (!last.empty() && key != last) std::fprintf(table.get(), "\n\n");
    last = key;
    if (r.error < 100 * ref.agreement) continue;
    std::fprintf(table.get(), "%s %s %.1e %.6e %.6e %.6e %lld %.6e\n", r.series.c_str(), r.method.c_str(), r.tol,
                 r.error, r.timing.fastest_wall, r.timing.fastest_cpu, r.evaluations, r.timing.slowest_cpu);
  }
  table.commit();
}

// Dopri5 with and without the check on springs that turn: the global error in tolerances and the work.
void write_spring_turn(const std::string& dir, const std::vector<Row>& rows, const ComparisonPlan& plan,
                       double floor, const std::string& command) {
  MarkdownTable turn({"rtol = atol", "error at T / tolerance", "evaluations",
                      "with `--max-spring-turn 0.5`: error / tolerance", "evaluations"},
                     "rrrrr");
  for (const double tol : plan.tolerances) {
    std::vector<std::string> cells = {format_number(tol)};
    for (const char* series : {"project_rms", "project_rms_turn"}) {
      const auto r = std::find_if(rows.begin(), rows.end(),
                                  [&](const Row& x) { return is(x, series, "dopri5") && x.tol == tol; });
      const bool shown = r != rows.end() && r->error >= floor;
      cells.push_back(shown ? format_number(r->error / tol, 2) : "-");
      cells.push_back(shown ? std::to_string(r->evaluations) : "-");
    }
    turn.add_row(cells);
  }
  write_table_fragment(dir + "spring_turn.md", turn, command);
}

// What one evaluation of the right-hand side costs inside odeint's dopri5, with the plain loop and with the
// project's forces: the run with the most evaluations of each, thread CPU time over evaluations.
void write_evaluation_cost(const std::string& dir, const std::vector<Row>& rows, const std::string& command) {
  MarkdownTable cost({"right-hand side", "evaluations", "microseconds per evaluation (odeint dopri5 run)"}, "lrr");
  for (const char* series : {"odeint_plain", "odeint_project_forces"}) {
    const Row* most = nullptr;
    for (const Row& r : rows)
      if (is(r, series, "dopri5") && (!most || r.evaluations > most->evaluations)) most = &r;
    if (most)
      cost.add_row({std::string(series) == "odeint_plain" ? "plain loop (the reader's program)" : "the project's forces",
                    std::to_string(most->evaluations),
                    format_number(1e6 * most->timing.fastest_cpu / static_cast<double>(most->evaluations), 3)});
  }
  write_table_fragment(dir + "evaluation_cost.md", cost, command);
}

// At each error level: the cheapest run of each side that reaches it, and the ratios of the project's time to
// odeint's. Three comparisons, each stated with the number of configurations it chooses from: the project's best
// of all its configurations against the straightforward odeint dopri5 program; the same two pairs on each side
// with the same norm on the same forces (as many tries each); and dopri5 against dopri5.
void write_levels(const std::string& dir, const std::vector<Row>& rows, double floor, const std::string& command) {
  OutputFile levels(dir + "levels.dat");
  std::fprintf(levels.get(), "# (thread CPU seconds, fastest of the timed runs) level_m project_best project_best_s "
                             "project_two_pairs_s odeint_dopri5_plain_s odeint_two_pairs_project_forces_s "
                             "project_dopri5_max_s odeint_dopri5_project_forces_s\n");
  MarkdownTable table({"error at T", "fastest project run, any configuration", "[ms]", "odeint dopri5, plain [ms]",
                       "project / odeint plain", "project, dopri5 or cash_karp [ms]",
                       "odeint, dopri5 or cash_karp54, project forces [ms]", "ratio, as many tries",
                       "dopri5 / dopri5"},
                      "llrrrrrrr");
  for (int k = 3; k <= 8; ++k) {
    const double level = std::pow(10.0, -k);
    if (level < floor) continue;  // not measurable against this reference
    const Row* best = nullptr;
    const double any = cheapest(rows, level, [](const Row& r) { return r.series.rfind("project", 0) == 0; }, &best);
    const double plain = cheapest(rows, level, [](const Row& r) { return is(r, "odeint_plain", "dopri5"); });
    const double mine2 = cheapest(rows, level, in_fair_project_set);
    const double theirs2 = cheapest(rows, level, [](const Row& r) { return r.series == "odeint_project_forces"; });
    const double mine1 = cheapest(rows, level, [](const Row& r) { return is(r, "project_max", "dopri5"); });
    const double theirs1 = cheapest(rows, level, [](const Row& r) { return is(r, "odeint_project_forces", "dopri5"); });
    std::string which = "-";
    if (best) {
      std::string options = best->series.substr(8);  // "rms", "max", "rms_elementary", "rms_turn"
      std::replace(options.begin(), options.end(), '_', ' ');
      which = "`" + best->method + "` " + options + ", tol " + format_number(best->tol, 2);
    }
    std::string word = which;
    std::replace(word.begin(), word.end(), ' ', '_');
    std::fprintf(levels.get(), "%.0e %s %.4e %.4e %.4e %.4e %.4e %.4e\n", level, word.c_str(), any, mine2, plain,
                 theirs2, mine1, theirs1);
    table.add_row({"1e-" + std::to_string(k) + " m", which, ms(any), ms(plain), ratio(any / plain), ms(mine2),
                   ms(theirs2), ratio(mine2 / theirs2), ratio(mine1 / theirs1)});
  }
  levels.commit();
  write_table_fragment(dir + "levels.md", table, command);
}

// How many configurations each comparison chose from, and the spread of the repetitions.
void write_tries(const std::string& dir, const std::vector<Row>& rows, const ComparisonPlan& plan) {
  const auto count = [&](const std::function<bool(const Row&)>& keep) {
    return std::to_string(std::count_if(rows.begin(), rows.end(), keep));
  };
  std::vector<double> spreads;
  for (const Row& r : rows) spreads.push_back(r.timing.slowest_cpu / r.timing.fastest_cpu);
  std::sort(spreads.begin(), spreads.end());
  std::string text =
      "The project's fastest run of a level is chosen from " +
      count([](const Row& r) { return r.series.rfind("project", 0) == 0; }) +
      " configurations (every pair with each norm, and the two dopri5 variants, at " +
      std::to_string(plan.tolerances.size()) + " tolerances), the straightforward odeint program's from " +
      count([](const Row& r) { return is(r, "odeint_plain", "dopri5"); }) +
      " (its dopri5 at the same tolerances): a head start for the project, said with both counts. The column "
      "\"as many tries\" gives each side the same choice: the project's dopri5 and cash_karp with the max norm (" +
      count(in_fair_project_set) + " configurations) against odeint's dopri5 and cash_karp54, whose error checker "
      "also takes the largest component, on the same forces (" +
      count([](const Row& r) { return r.series == "odeint_project_forces"; }) +
      "); the last column compares dopri5 with dopri5, one configuration per tolerance on each side.";
  if (!spreads.empty())
    text += " Each time is the fastest of " + std::to_string(plan.runs) +
            " repetitions; the slowest repetition of a run took at most " + format_fixed(spreads.back(), 2) +
            " times its fastest (median " + format_fixed(spreads[spreads.size() / 2], 2) + " over the " +
            std::to_string(spreads.size()) + " runs), so ratios closer to 1 than that do not rank the two sides.";
  write_text_fragment(dir + "tries.md", text + "\n");
}

}  // namespace

void write_reference(const std::string& dir, const Reference& ref, double T, const std::string& command) {
  write_text_fragment(dir + "reference.md",
                      "The reference of this run is odeint's Dormand-Prince in `long double` at rtol = atol = " +
                          format_number(ref.tolerance) + " (" + std::to_string(ref.steps) +
                          " steps); the same computation with Cash-Karp (" + std::to_string(ref.check_steps) +
                          " steps) lands " + format_number(ref.agreement, 2) + " m from it at T = " +
                          format_number(T) + " s, so errors below " + format_number(100 * ref.agreement, 2) +
                          " m are not plotted (`" + command + "`).\n");
}

void write_comparison(const std::string& dir, const std::vector<Row>& rows, const Reference& ref,
                      const ComparisonPlan& plan, const SceneParams& scene, const std::string& command) {
  const double floor = 100 * ref.agreement;  // errors below this are not measurements
  write_table(dir, rows, ref, plan.run.t_end, scene);
  write_spring_turn(dir, rows, plan, floor, command);
  write_evaluation_cost(dir, rows, command);
  write_levels(dir, rows, floor, command);
  write_tries(dir, rows, plan);
}

}  // namespace ch08
