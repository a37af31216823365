// The speed comparison on the stiff cloth (K, D) = (5000, 20) over T = 0.4 s: CVODE and ARKODE against the book's
// implicit methods, and for each error level the fastest run of each that reaches it, with the work behind its time.
#include "benchmark.hpp"

#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <cmath>
#include <cstdio>
#include <tuple>
#include <utility>
#include <vector>

using namespace cloth;

namespace ch09 {
namespace {

/// The runs on the stiff cloth: CVODE's and ARKODE's at each tolerance, the book's at each tolerance or step.
struct StiffRuns {
  std::vector<Timed> cvode, arkode, book;
  int repeats = 1;
  double reference_change = 0;  // how far the reference moves when its step is halved [m]
};

// The SUNDIALS runs as their documentation recommends them (KLU, the analytic Jacobian, y at T a step's own value):
// CVODE's BDF with its default orders 1-5 and capped at 2; ARKODE's ESDIRK3(2)4L[2]SA and ESDIRK4(3)6L[2]SA with T
// as a stop time; each also given the book's definite df/dx. The quick run: the exact Jacobian, no order cap, and
// ARKODE down to 1e-3.
void sundials_runs(ForceField& field, const Timing& timing, bool quick, StiffRuns& runs) {
  const int k_step = quick ? 4 : 1;  // every fourth rung of 10^(-k/4) in the quick run (1e-2, 1e-3, ...)
  for (const StiffnessTreatment treatment : {StiffnessTreatment::exact, StiffnessTreatment::definite}) {
    if (quick && treatment != StiffnessTreatment::exact) continue;
    const std::string jacobian = treatment == StiffnessTreatment::exact ? "" : ", definite Jacobian";
    for (int k = 8; k <= 28; k += k_step) {
      const double tol = std::pow(10.0, -k / 4.0);
      for (const int max_order : {5, 2}) {
        if (quick && max_order != 5) continue;
        SundialsSettings cvode{"cvode-bdf"};
        cvode.max_order = max_order;
        cvode.treatment = treatment;
        const std::string who = max_order < 5 ? "CVODE BDF, order <= 2" : "CVODE BDF";
        runs.cvode.push_back(sundials_timed_run(field, cvode, tol, who + jacobian, timing));
      }
      for (const auto& [solver, table] : {std::pair{"arkode-esdirk32", "ESDIRK3(2)4L[2]SA"},
                                          std::pair{"arkode-esdirk43", "ESDIRK4(3)6L[2]SA"}}) {
        if (quick && k > 12) continue;  // seconds a run below 1e-3: the full run's
        SundialsSettings arkode{solver};
        arkode.treatment = treatment;
        runs.arkode.push_back(sundials_timed_run(field, arkode, tol, std::string("ARKODE ") + table + jacobian, timing));
      }
    }
  }
}

// [speed_comparison]
// On the stiff cloth (5000, 20) over T = 0.4 s: the SUNDIALS runs above, the book's embedded pairs at the tolerances
// 10^(-k/4), and the book's SDIRKs at a ladder of fixed steps.
StiffRuns stiff_runs(const SceneParams& base, bool quick) {
  SceneParams p = base;
  p.stiffness = 5000;
  p.damping = 20;
  const double T = 0.4;
  StiffRuns runs;
  runs.repeats = quick ? 1 : 3;
  const Scene scene(p);
  ForceField field(scene);
  const Vector reference = rk4_positions(field, T, 2e-5);
  runs.reference_change = largest_distance(reference, rk4_positions(field, T, 1e-5));
  const Timing timing{T, reference, runs.repeats};
  sundials_runs(field, timing, quick, runs);
  // The quick run (the plots target) takes every fourth rung and the two ESDIRK pairs only; the full run every
  // rung, TR-BDF2 and fixed steps.
  const int k_step = quick ? 4 : 1;
  for (const char* pair : {"trbdf2", "esdirk32", "esdirk43"})
    for (int k = 4; k <= 24; k += k_step)
      if (!quick || std::string(pair) != "trbdf2")
        runs.book.push_back(controlled_run(field, pair, std::pow(10.0, -k / 4.0), timing));
  if (quick) return runs;
  const struct {
    const char* method;
    double h, newton_tol;
  } book_runs[] = {{"sdirk2", 0.005, 1e-4},   {"sdirk2", 0.0025, 1e-4}, {"sdirk3", 0.0025, 1e-4},
                   {"sdirk3", 0.0016, 1e-4},  {"sdirk3", 0.00125, 1e-4}, {"sdirk3", 0.0008, 1e-5},
                   {"sdirk3", 0.000625, 1e-5}};
  for (const auto& r : book_runs)
    runs.book.push_back(fixed_step_run(field, r.method, r.h, r.newton_tol, NewtonVariant::modified, timing));
  return runs;
}

// For an error level, the fastest of `runs` that reaches it (nullptr when none does).
const Timed* fastest_reaching(const std::vector<Timed>& runs, double level) {
  const Timed* best = nullptr;
  for (const Timed& t : runs)
    if (t.error <= level && (best == nullptr || t.seconds < best->seconds)) best = &t;
  return best;
}
// [speed_comparison]

// Every run into stiff_runs.dat (the figure): index 0 CVODE's, 1 ARKODE's, 2 the book's; then, for each level,
// the time of each one's fastest run reaching it (indices 3, 4 and 5, the diagram's lines).
void write_runs(const StiffRuns& runs, const std::string& path) {
  OutputFile all(path);
  std::fprintf(all.get(), "# stiff cloth K = 5000, D = 20, T = 0.4 s; error against RK4 at h = 2e-5 [m] (which moves "
               "%.2e m at h = 1e-5), thread processor seconds (best of %d)\n# index 0: CVODE BDF + KLU, index 1: "
               "ARKODE ESDIRK + KLU, index 2: the book's methods\n"
               "# error seconds factorizations jacobians newton_iterations forces \"run\"\n",
               runs.reference_change, runs.repeats);
  const std::vector<const std::vector<Timed>*> sides = {&runs.cvode, &runs.arkode, &runs.book};
  for (const auto* side : sides) {
    for (const Timed& t : *side)
      std::fprintf(all.get(), "%.6e %.6f %lld %lld %lld %lld \"%s, %s\"\n", t.error, t.seconds, t.factorizations,
                   t.jacobians, t.newton_iterations, t.forces, t.solver.c_str(), t.setting.c_str());
    std::fprintf(all.get(), "\n\n");
  }
  for (const auto* side : sides) {
    for (int k = 8; k <= 24; ++k)
      if (const Timed* t = fastest_reaching(*side, std::pow(10.0, -k / 4.0)))
        std::fprintf(all.get(), "%.6e %.6f\n", std::pow(10.0, -k / 4.0), t->seconds);
    std::fprintf(all.get(), "\n\n");
  }
  all.commit();
}

// A run's cells in the comparison: who and with what (`missing` when no run reached the level), the error it
// reached (with_error), its time.
std::vector<std::string> cells(const Timed* t, bool with_error, const char* missing) {
  std::vector<std::string> row = {t == nullptr ? missing : t->solver + ", " + t->setting};
  if (with_error) row.push_back(t == nullptr ? "" : format_number(t->error, 2));
  row.push_back(t == nullptr ? "" : format_number(t->seconds, 2));
  return row;
}

}  // namespace

// For each error level the fastest run of each side and the ratio of their processor times into
// stiff_comparison.md, and their work into stiff_work.md (the page's tables).
void stiff_comparison(const SceneParams& base, bool quick, const std::string& dir, const std::string& command) {
  const StiffRuns runs = stiff_runs(base, quick);
  write_runs(runs, dir + "/stiff_runs.dat");
  MarkdownTable table({"error level [m]", "CVODE's fastest run reaching it", "error [m]", "time [s]",
                       "ARKODE's fastest run reaching it", "time [s]", "the book's fastest run reaching it",
                       "error [m]", "time [s]", "book / CVODE", "book / ARKODE"},
                      "rlrrlrlrrrr");
  // SUNDIALS' factorizations are its linear solver setups (each a new I - gamma J factored by KLU).
  MarkdownTable work({"error level [m]", "run", "factorizations", "Jacobians", "Newton iterations",
                      "force evaluations"},
                     "rlrrrr");
  for (const double level : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    const Timed* c = fastest_reaching(runs.cvode, level);
    const Timed* a = fastest_reaching(runs.arkode, level);
    const Timed* b = fastest_reaching(runs.book, level);
    std::vector<std::string> row = {format_number(level)};
    // The quick run stops ARKODE at 1e-3: a level below it is one it was not asked for.
    const char* arkode_missing = quick && level < 1e-3 ? "not run (quick form)" : "none";
    for (const auto& [t, with_error, missing] : {std::tuple{c, true, "none"}, std::tuple{a, false, arkode_missing},
                                                 std::tuple{b, true, "none"}})
      for (const std::string& cell : cells(t, with_error, missing)) row.push_back(cell);
    row.push_back(c && b ? format_number(b->seconds / c->seconds, 2) : "");
    row.push_back(a && b ? format_number(b->seconds / a->seconds, 2) : "");
    table.add_row(row);
    for (const Timed* t : {c, a, b})
      if (t != nullptr)
        work.add_row({format_number(level), t->solver + ", " + t->setting, std::to_string(t->factorizations),
                      std::to_string(t->jacobians), std::to_string(t->newton_iterations), std::to_string(t->forces)});
  }
  write_table_fragment(dir + "/stiff_comparison.md", table, command);
  write_table_fragment(dir + "/stiff_work.md", work, command);
  write_text_fragment(dir + "/stiff_reference.md",
                      "The reference is RK4 at h = 2·10⁻⁵ s; at h = 10⁻⁵ s it moves by " +
                          format_number(runs.reference_change, 2) + " m, so it is good to that order at every "
                          "level of the table.\n");
}

}  // namespace ch09
