// Chapter 8's benchmark: error at T against in-process time for the project's adaptive pairs and for Boost.Odeint's
// controlled runge_kutta_dopri5 and runge_kutta_cash_karp54, each odeint stepper built twice: as the
// straightforward program a reader would write (plain_cloth.hpp) and driving the project's own forces. Errors are
// measured against a long-double reference computed here and checked against a second one.
#include "plain_cloth.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/adaptive_simulate.hpp"
#include "integrators/method_registry.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

using namespace cloth;
namespace odeint = boost::numeric::odeint;

namespace {

using State = std::vector<double>;
using LongState = std::vector<long double>;

double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Best of `runs` calls of body(): the run least disturbed by other processes (wall and thread CPU time).
struct Timing {
  double wall = 1e300, cpu = 1e300;
  double cpu_slowest = 0;  ///< the slowest repetition: with `cpu`, the spread of the timings
};
Timing best_of(int runs, const std::function<void()>& body) {
  Timing best;
  for (int k = 0; k < runs; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_seconds();
    body();
    throw_if_interrupted();  // between two timings, and after a run a signal cut short
    const double cpu = thread_seconds() - c0;
    best.cpu = std::min(best.cpu, cpu);
    best.cpu_slowest = std::max(best.cpu_slowest, cpu);
    best.wall = std::min(best.wall, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

// Largest distance of a free particle from the reference at T.
template <class X>
double position_error(const X& x, const LongState& ref) {
  double worst = 0;
  for (std::size_t k = 0; k + 2 < ref.size() / 2; k += 3) {
    long double d2 = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const long double d = static_cast<long double>(x[static_cast<Eigen::Index>(k + c)]) - ref[k + c];
      d2 += d * d;
    }
    worst = std::max(worst, static_cast<double>(std::sqrt(d2)));
  }
  return worst;
}

// [reference]
// The reference: odeint's controlled Dormand-Prince on the plain right-hand side in long double at tolerance
// `tol`; its credential is its distance from the same computation with Cash-Karp, a different pair.
template <class Stepper>
LongState long_double_run(const Scene& scene, double T, double tol, long long& steps) {
  ch08::PlainCloth<long double> plain(scene);
  // odeint is C++: the exception of a stop request (SIGINT, SIGTERM) passes through it, within one evaluation.
  const auto rhs = [&plain](const LongState& s, LongState& d, long double t) {
    throw_if_interrupted();
    plain(s, d, static_cast<double>(t));
  };
  LongState y = ch08::PlainCloth<long double>::initial_state(scene);
  steps = static_cast<long long>(odeint::integrate_adaptive(odeint::make_controlled<Stepper>(static_cast<long double>(tol), static_cast<long double>(tol)), rhs,
                                                            y, 0.0L, static_cast<long double>(T), 1e-4L));
  return y;
}
// [reference]

struct Row {
  std::string series, method;
  double tol;
  double error, wall, cpu;
  long long evaluations;
  double cpu_slowest;
};

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int runs = 5;
  CommandLine cli("ch08_work_precision",
                  "Chapter 8: work-precision of the adaptive pairs against Boost.Odeint on the report's cloth.\n"
                  "--t-end is the horizon; --K, --damping and the other scene flags apply.");
  // The scene flags and the horizon; no --dt or --frames: every run chooses its own steps and records no frames.
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--K-flexion", "--damping", "--damping-model", "--springs",
                  "--pins", "--v0", "--t-end", "--out"});
  cli.set_default("--t-end", "1");  // the whole fall through the first folds, as Chapter 8's diagrams show it
  cli.add_switch("--quick", "a reduced sweep for the plots target (well under a minute)", [&] { quick = true; });
  cli.add_value("--runs", "N", "timed runs per point, the best is kept (default 5)",
                [&](const std::string& s) { runs = static_cast<int>(parse_count(s, 1, 100)); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const double T = opt.run.t_end;
    prepare_outputs(opt.run.out_dir, {"work_precision.dat", "levels.dat", "levels.md", "reference.md",
                                      "spring_turn.md", "evaluation_cost.md", "tries.md"});
    const std::string command = reader_command(argc, argv);
    const Scene scene(opt.scene);
    const std::string dir = opt.run.out_dir + "/";

    // The reference and its credential.
    const double ref_tol = quick ? 1e-10 : 1e-14;
    long long ref_steps = 0, check_steps = 0;
    const auto r0 = std::chrono::steady_clock::now();
    const LongState ref = long_double_run<odeint::runge_kutta_dopri5<LongState, long double, LongState, long double>>(scene, T, ref_tol, ref_steps);
    const LongState check = long_double_run<odeint::runge_kutta_cash_karp54<LongState, long double, LongState, long double>>(scene, T, ref_tol, check_steps);
    const double agreement = position_error(Eigen::Map<const Eigen::Matrix<long double, Eigen::Dynamic, 1>>(check.data(), static_cast<Eigen::Index>(check.size())), ref);
    std::printf("reference: long double, odeint dopri5 and cash_karp54 at tol %g (%lld and %lld steps, %.1f s): "
                "they agree to %.2e m at T = %g s\n",
                ref_tol, ref_steps, check_steps,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - r0).count(), agreement, T);
    const double floor = 100 * agreement;  // errors below this are not measurements
    write_text_fragment(dir + "reference.md",
                        "The reference of this run is odeint's Dormand-Prince in `long double` at rtol = atol = " +
                            format_number(ref_tol) + " (" + std::to_string(ref_steps) +
                            " steps); the same computation with Cash-Karp (" + std::to_string(check_steps) +
                            " steps) lands " + format_number(agreement, 2) + " m from it at T = " + format_number(T) +
                            " s, so errors below " + format_number(floor, 2) + " m are not plotted (`" + command +
                            "`).\n");

    std::vector<Row> rows;
    std::vector<double> tolerances;
    for (int k = quick ? 3 : 2; k <= (quick ? 8 : 11); ++k) tolerances.push_back(std::pow(10.0, -k));
    for (int k = quick ? 3 : 2; k <= (quick ? 7 : 10); ++k) tolerances.push_back(3 * std::pow(10.0, -k - 1));
    std::sort(tolerances.begin(), tolerances.end(), std::greater<>());

    RunSettings run = opt.run;
    run.t_end = T;
    // [project_runs]
    // Besides every pair with each norm (PI controller): dopri5 with the elementary controller, and dopri5 refusing
    // steps across which a spring turns by more than 0.5 rad.
    int project_tries = 0;  // configurations tried on each side: the best of more tries is a head start
    const auto project_run = [&](const std::string& series, const ButcherTableau& tableau, double tol,
                                 const AdaptiveSettings& settings) {
      ++project_tries;
      ForceField field(scene);
      EmbeddedRungeKutta rk(field, tableau);
      AdaptiveResult result;
      const Timing t = best_of(runs, [&] { result = adaptive_simulate(rk, run, settings, false); });
      if (result.status != RunStatus::ok) return;
      rows.push_back({series, tableau.name, tol, position_error(result.x, ref), t.wall, t.cpu,
                      result.counters.rhs_evaluations, t.cpu_slowest});
    };
    for (const Method* row : methods_of(MethodFamily::embedded_runge_kutta)) {
      const ButcherTableau& tableau = *row->tableau;
      if (tableau.name == "heun_euler") continue;  // order 2: far off the diagram at these errors
      for (const NormKind norm : {NormKind::rms, NormKind::max})
      for (const double tol : tolerances) {
        AdaptiveSettings settings;
        settings.tolerances = {tol, tol, norm};
        project_run(std::string("project_") + norm_name(norm), tableau, tol, settings);
      }
    }
    for (const double tol : tolerances) {
      AdaptiveSettings settings;
      settings.tolerances = {tol, tol};
      settings.controller = ControllerKind::elementary;
      project_run("project_rms_elementary", embedded_tableau_from_argument("dopri5"), tol, settings);
      settings.controller = ControllerKind::pi;
      settings.max_spring_turn = 0.5;
      project_run("project_rms_turn", embedded_tableau_from_argument("dopri5"), tol, settings);
    }
    // [project_runs]
    // [odeint_runs]
    // Boost.Odeint as its documentation shows it: integrate_adaptive with a controlled stepper made by
    // make_controlled(atol, rtol), from a first step of 1e-4 s (odeint adapts it from there).
    int odeint_project_force_tries = 0;
    const auto odeint_run = [&](const std::string& method, const std::string& series, double tol, auto stepper,
                                auto&& rhs, long long& calls) {
      if (series == "odeint_project_forces") ++odeint_project_force_tries;
      State y = ch08::PlainCloth<double>::initial_state(scene);
      calls = 0;
      const Timing t = best_of(runs, [&] {
        y = ch08::PlainCloth<double>::initial_state(scene);
        calls = 0;
        odeint::integrate_adaptive(stepper, [&](const State& s, State& d, double time) {
                                     throw_if_interrupted();
                                     ++calls;
                                     rhs(s, d, time);
                                   },
                                   y, 0.0, T, 1e-4);
      });
      rows.push_back({series, method, tol,
                      position_error(Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size())), ref),
                      t.wall, t.cpu, calls, t.cpu_slowest});
    };
    ch08::PlainCloth<double> plain(scene);
    ForceField field(scene);
    const int n = scene.dof_count();
    // The project's forces behind odeint's interface: the flat state seen as (x, v) without a copy.
    const auto project_rhs = [&](const State& y, State& dydt, double) {
      Eigen::Map<const Eigen::VectorXd> x(y.data(), n), v(y.data() + n, n);
      Eigen::Map<Eigen::VectorXd>(dydt.data(), n) = v;
      field.acceleration(x, v, Eigen::Map<Eigen::VectorXd>(dydt.data() + n, n));
    };
    for (const double tol : tolerances) {
      long long calls = 0;
      odeint_run("dopri5", "odeint_plain", tol, odeint::make_controlled<odeint::runge_kutta_dopri5<State>>(tol, tol),
                 plain, calls);
      odeint_run("cash_karp54", "odeint_plain", tol,
                 odeint::make_controlled<odeint::runge_kutta_cash_karp54<State>>(tol, tol), plain, calls);
      odeint_run("dopri5", "odeint_project_forces", tol,
                 odeint::make_controlled<odeint::runge_kutta_dopri5<State>>(tol, tol), project_rhs, calls);
      odeint_run("cash_karp54", "odeint_project_forces", tol,
                 odeint::make_controlled<odeint::runge_kutta_cash_karp54<State>>(tol, tol), project_rhs, calls);
    }
    // [odeint_runs]

    OutputFile table(dir + "work_precision.dat");
    std::fprintf(table.get(), "# series method tol error_at_T_m wall_s cpu_s evaluations  (T = %g s, K = %g, D = %g; "
                              "reference agreement %.3e m; blocks by series and method)\n",
                 T, opt.scene.stiffness, opt.scene.damping, agreement);
    std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
      return a.series != b.series ? a.series < b.series : a.method < b.method;
    });
    std::string last;
    for (const Row& r : rows) {
      const std::string key = r.series + " " + r.method;
      if (!last.empty() && key != last) std::fprintf(table.get(), "\n\n");
      last = key;
      if (r.error < floor) continue;
      std::fprintf(table.get(), "%s %s %.1e %.6e %.6e %.6e %lld\n", r.series.c_str(), r.method.c_str(), r.tol, r.error,
                   r.wall, r.cpu, r.evaluations);
    }
    table.commit();

    // Dopri5 with and without the check on springs that turn: the global error in tolerances and the work.
    MarkdownTable turn({"rtol = atol", "error at T / tolerance", "evaluations",
                        "with `--max-spring-turn 0.5`: error / tolerance",
                        "evaluations"},
                       "rrrrr");
    for (const double tol : tolerances) {
      const Row* plain_row = nullptr;
      const Row* turn_row = nullptr;
      for (const Row& r : rows)
        if (r.method == "dopri5" && r.tol == tol) {
          if (r.series == "project_rms") plain_row = &r;
          if (r.series == "project_rms_turn") turn_row = &r;
        }
      const auto cells = [&](const Row* r) -> std::vector<std::string> {
        if (!r || r->error < floor) return {"-", "-"};
        return {format_number(r->error / tol, 2), std::to_string(r->evaluations)};
      };
      const auto a = cells(plain_row), b = cells(turn_row);
      turn.add_row({format_number(tol), a[0], a[1], b[0], b[1]});
    }
    write_table_fragment(dir + "spring_turn.md", turn, command);

    // What one evaluation of the right-hand side costs inside odeint's dopri5, with the plain loop and with the
    // project's forces: the run with the most evaluations of each, thread CPU time over evaluations.
    MarkdownTable cost({"right-hand side", "evaluations", "microseconds per evaluation (odeint dopri5 run)"}, "lrr");
    for (const char* series : {"odeint_plain", "odeint_project_forces"}) {
      const Row* most = nullptr;
      for (const Row& r : rows)
        if (r.series == series && r.method == "dopri5" && (!most || r.evaluations > most->evaluations)) most = &r;
      if (most)
        cost.add_row({std::string(series) == "odeint_plain" ? "plain loop (the reader's program)" : "the project's forces",
                      std::to_string(most->evaluations), format_number(1e6 * most->cpu / static_cast<double>(most->evaluations), 3)});
    }
    write_table_fragment(dir + "evaluation_cost.md", cost, command);

    // At each error level: the cheapest run of each series that reaches it (thread CPU time, best of the timed
    // runs: on a shared machine the wall clock also counts the time the thread waited for a core), and the
    // ratios of the project's time to odeint's.
    OutputFile levels(dir + "levels.dat");
    std::fprintf(levels.get(), "# (thread CPU seconds) level_m project_best project_seconds odeint_dopri5_plain_s odeint_cash_karp54_plain_s "
                               "odeint_dopri5_project_forces_s odeint_cash_karp54_project_forces_s "
                               "ratio_to_dopri5_plain ratio_to_best_odeint_project_forces\n");
    MarkdownTable level_table({"error at T", "fastest project run", "project [ms]", "odeint dopri5, plain [ms]",
                               "odeint cash_karp54, plain [ms]", "odeint dopri5, project forces [ms]",
                               "odeint cash_karp54, project forces [ms]", "project / odeint dopri5 plain",
                               "project / best odeint on project forces",
                               "project dopri5 (rms, PI) / odeint dopri5, project forces"},
                              "llrrrrrrrr");
    const auto ms = [](double seconds) { return std::isnan(seconds) ? std::string("-") : format_number(1e3 * seconds, 3); };
    const auto ratio = [](double x) { return std::isnan(x) ? std::string("-") : format_fixed(x, 2); };
    for (int k = 3; k <= 8; ++k) {
      const double level = std::pow(10.0, -k);
      if (level < floor) continue;  // not measurable against this reference
      // [levels]
      // The least CPU time of a run of `series` (and `method`, unless empty) whose error at T is within `level`.
      const auto cheapest = [&](const std::string& series, const std::string& method, std::string* which) {
        double best = 1e300;
        for (const Row& r : rows)
          if (r.series.rfind(series, 0) == 0 && (method.empty() || r.method == method) && r.error <= level &&
              r.cpu < best) {
            best = r.cpu;
            if (which) {
              std::string options = r.series.substr(8);  // "rms", "max", "rms_elementary", "rms_turn"
              std::replace(options.begin(), options.end(), '_', ' ');
              *which = "`" + r.method + "` " + options + ", tol " + format_number(r.tol, 2);
            }
          }
        return best < 1e300 ? best : std::nan("");  // nan: no run of the series reached the level
      };
      // [levels]
      std::string which = "-";  // for the page; levels.dat gets it without spaces
      const double mine = cheapest("project", "", &which);
      const double dp = cheapest("odeint_plain", "dopri5", nullptr), ck = cheapest("odeint_plain", "cash_karp54", nullptr);
      const double dpf = cheapest("odeint_project_forces", "dopri5", nullptr);
      const double ckf = cheapest("odeint_project_forces", "cash_karp54", nullptr);
      std::string which_word = which;
      std::replace(which_word.begin(), which_word.end(), ' ', '_');
      std::fprintf(levels.get(), "%.0e %s %.4e %.4e %.4e %.4e %.4e %.3f %.3f\n", level, which_word.c_str(), mine, dp, ck, dpf,
                   ckf, mine / dp, mine / std::fmin(dpf, ckf));
      std::printf("error <= %.0e m: project %s %.2f ms | odeint plain dopri5 %.2f ms, cash_karp54 %.2f ms | odeint on "
                  "the project's forces dopri5 %.2f ms, cash_karp54 %.2f ms | project / plain dopri5 = %.2f, project / "
                  "best odeint on project forces = %.2f\n",
                  level, which.c_str(), 1e3 * mine, 1e3 * dp, 1e3 * ck, 1e3 * dpf, 1e3 * ckf, mine / dp,
                  mine / std::fmin(dpf, ckf));
      // The like-for-like column: the same pair, one configuration per tolerance on each side, the same forces.
      double same_pair = std::nan("");
      for (const Row& r : rows)
        if (r.series == "project_rms" && r.method == "dopri5" && r.error <= level && !(r.cpu >= same_pair)) same_pair = r.cpu;
      level_table.add_row({"1e-" + std::to_string(k) + " m", which, ms(mine), ms(dp), ms(ck), ms(dpf), ms(ckf), ratio(mine / dp),
                           ratio(mine / std::fmin(dpf, ckf)), ratio(same_pair / dpf)});
    }
    levels.commit();
    write_table_fragment(dir + "levels.md", level_table, command);
    // The spread of the repetitions: the slowest over the fastest, for every timed run of both sides.
    std::vector<double> spreads;
    for (const Row& r : rows) spreads.push_back(r.cpu_slowest / r.cpu);
    std::sort(spreads.begin(), spreads.end());
    const std::string spread =
        spreads.empty() ? std::string()
                        : " Each time is the fastest of " + std::to_string(runs) + " repetitions; the slowest repetition of a "
                          "run took at most " + format_fixed(spreads.back(), 2) + " times its fastest (median " +
                          format_fixed(spreads[spreads.size() / 2], 2) + " over the " + std::to_string(spreads.size()) +
                          " runs), so ratios closer to 1 than that do not rank the two sides.";
    write_text_fragment(dir + "tries.md",
                        "The fastest project run of a level is the best of " + std::to_string(project_tries) +
                            " configurations (every pair with each norm and the two dopri5 variants, at " +
                            std::to_string(tolerances.size()) + " tolerances), the best odeint run on the project's "
                            "forces the best of " + std::to_string(odeint_project_force_tries) +
                            " (two steppers at the same tolerances); the last column compares one configuration with "
                            "one, dopri5 against dopri5 at the same tolerances." + spread + "\n");
    return 0;
  });
}
