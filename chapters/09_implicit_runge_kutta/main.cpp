// Chapter 9: any diagonally implicit Runge-Kutta method, given by its Butcher tableau, and BDF2 on the report's
// cloth, every stage solved by the one Newton machinery of the library; step control for an embedded pair; and
// the chapter's studies (energy on the undamped cloth, observed orders, work against precision on the stiff one).
#include "program/command_line.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "base/text.hpp"
#include "analysis/fastest_modes.hpp"
#include "analysis/stability_function.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/implicit_step_control.hpp"
#include "integrators/simulate.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/limits.hpp"
#include "program/method_flags.hpp"
#include "program/method_tables.hpp"
#include "program/output.hpp"
#include "program/run_outputs.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sys/stat.h>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// Newton's tolerance as a fraction of the step control's error tolerance (Hairer & Wanner 1996, IV.8, kappa).
constexpr double newton_kappa = 0.1;

// What the command line chose: a registered implicit method or a tableau file, Newton's settings, step control.
struct MethodChoice {
  std::string argument = "sdirk2";  // --tableau as given
  const Method* row = nullptr;      // the registry's row, or nullptr for a tableau file
  ImplicitTableau tableau;          // the tableau, for a Runge-Kutta method (empty for a multistep one)
  NewtonSettings newton;
  std::optional<double> tol;  // --tol: step control

  [[nodiscard]] bool multistep() const { return row != nullptr && row->family == MethodFamily::multistep; }
};

// A registered method by its name, or else a tableau file; the message lists the registered names.
MethodChoice choose(const std::string& argument) {
  MethodChoice choice;
  choice.argument = argument;
  std::string names;
  for (const Method* m : newton_methods()) {
    if (m->name == argument) choice.row = m;
    names += (names.empty() ? "" : ", ") + m->name;
  }
  if (choice.row != nullptr) {
    if (!choice.multistep()) choice.tableau = builtin_implicit_tableau(argument);
    return choice;
  }
  struct stat info {};
  if (::stat(argument.c_str(), &info) != 0)
    throw InputError("--tableau: '" + escaped(argument) + "' is neither a registered implicit method (" + names +
                     ") nor a readable tableau file");
  try {
    choice.tableau = read_implicit_tableau(argument);
  } catch (const InputError& e) {
    throw InputError(std::string("--tableau: ") + e.what());
  }
  return choice;
}

std::unique_ptr<NewtonStepper> make_method(const MethodChoice& choice, ForceField& field) {
  if (choice.row != nullptr) return make_newton_stepper(choice.row->name, field, {choice.newton});
  return std::make_unique<DiagonallyImplicitRungeKutta>(field, choice.tableau, choice.newton);
}

// run.txt's lines for the method: the tableau, Newton, the linear algebra, the work.
std::vector<std::pair<std::string, std::string>> method_lines(const MethodChoice& choice, const Stepper& stepper,
                                                              const RunResult& result, const NewtonSettings& newton) {
  std::vector<std::pair<std::string, std::string>> lines;
  if (choice.multistep()) {
    lines.emplace_back("tableau", choice.row->name + " (multistep)");
    lines.emplace_back("order", "2");
  } else {
    lines.emplace_back("tableau", choice.tableau.method.name);
    lines.emplace_back("tableau_source", choice.tableau.source);
    lines.emplace_back("stages", std::to_string(choice.tableau.method.stages()));
    lines.emplace_back("order", std::to_string(choice.tableau.method.order));
  }
  lines.emplace_back("newton", newton_variant_name(newton.one_iteration() ? NewtonVariant::one : newton.variant));
  lines.emplace_back("linear_solver", linear_solver_name(resolve(newton, stepper.field().scene()).solver));
  lines.emplace_back("jacobian", stiffness_treatments().name(newton.treatment));
  lines.emplace_back("newton_tol", format_number(newton.tolerance, 10));
  lines.emplace_back("newton_test", newton.estimate_test ? "estimate" : "update_and_residual");
  lines.emplace_back("newton_max_iter", std::to_string(newton.max_iterations));
  lines.emplace_back("line_search", line_searches().name(newton.line_search));
  lines.emplace_back("linear_solves", std::to_string(result.counters.linear_solves));
  lines.emplace_back("line_search_halvings", std::to_string(result.counters.line_search_halvings));
  return lines;
}

// One run of the chosen method on `params`, outputs in run.out_dir; returns report()'s exit status.
int run_cloth(const SceneParams& params, const RunSettings& run, const MethodChoice& choice,
              const std::string& program, RunResult* kept = nullptr) {
  const Scene scene(params);
  validate(choice.newton, scene);  // before anything is written
  ForceField field(scene);
  const std::unique_ptr<NewtonStepper> stepper = make_method(choice, field);
  prepare_outputs(run.out_dir, run_output_names());
  RunResult result;
  std::vector<std::pair<std::string, std::string>> extra;
  if (choice.tol) {
    StepControl control;
    control.tolerance = *choice.tol;
    ControlledRun controlled =
        simulate_controlled(dynamic_cast<DiagonallyImplicitRungeKutta&>(*stepper), run, control);
    result = std::move(controlled.result);
    extra = method_lines(choice, *stepper, result, choice.newton);
    extra.emplace_back("tol", format_number(*choice.tol, 10));
    extra.emplace_back("rejected_steps", std::to_string(controlled.rejected_steps));
    extra.emplace_back("newton_failures", std::to_string(controlled.newton_failures));
    extra.emplace_back("smallest_step", format_number(controlled.smallest_step, 6));
    extra.emplace_back("largest_step", format_number(controlled.largest_step, 6));
  } else {
    result = simulate(*stepper, run);
    extra = method_lines(choice, *stepper, result, choice.newton);
    extra.emplace_back("rejected_steps", "0");
  }
  write_outputs(result, *stepper, run, extra);
  const int status = report(result, *stepper, program);
  if (result.steps > 0)
    std::printf("  Newton iterations per step: %.3f (%lld in %lld steps), %lld factorizations, %lld linear solves\n",
                static_cast<double>(result.counters.newton_iterations) / static_cast<double>(result.steps),
                result.counters.newton_iterations, result.steps, result.counters.factorizations,
                result.counters.linear_solves);
  if (kept) *kept = std::move(result);
  return status;
}

// The methods the studies compare: every registered method StageNewton solves, in the registry's order.
std::vector<MethodChoice> study_methods(const NewtonSettings& newton) {
  std::vector<MethodChoice> methods;
  for (const Method* m : newton_methods()) {
    MethodChoice choice = choose(m->name);
    choice.newton = newton;
    methods.push_back(choice);
  }
  return methods;
}

// [energy_study]
// Every method on the undamped cloth (D = 0) at the run's h to its T: energy.dat per method in its own folder,
// and energy_summary.dat with E(T) / E(0) and the work. Returns 0, or 128 + signal when a run was interrupted: the
// interrupted run's own run.txt says so, and the summary, which would list it as finished, is not written.
int energy_study(const Options& opt, const NewtonSettings& newton, const std::string& dir,
                  const std::string& program, const std::string& command) {
  SceneParams p = opt.scene;
  p.damping = 0;
  OutputFile summary(dir + "/energy_summary.dat");
  std::fprintf(summary.get(), "# undamped cloth, K = %g, h = %g s, T = %g s\n# method E(T)/E(0) min_E/E(0) "
               "max_E/E(0) newton_iterations factorizations wall_seconds\n", p.stiffness, opt.run.dt, opt.run.t_end);
  NewtonSettings kept = newton;
  kept.variant = NewtonVariant::modified;  // converged to the same tolerance as full Newton, at a fraction of the cost
  const std::string scene = std::string("undamped cloth, h = ") + format_number(opt.run.dt) + " s, T = " +
                            format_number(opt.run.t_end) + " s";
  MarkdownTable table({scene, "E(T) / E(0)", "smallest E / E(0)", "largest E / E(0)"}, "lrrr");
  for (const MethodChoice& m : study_methods(kept)) {
    RunSettings run = opt.run;
    run.out_dir = dir + "/energy_" + m.argument;
    RunResult r;
    if (const int status = run_cloth(p, run, m, program, &r); status >= 128) return status;
    const double E0 = r.energy.front().energy.total();
    double lo = E0, hi = E0;
    for (const EnergySample& e : r.energy) lo = std::min(lo, e.energy.total()), hi = std::max(hi, e.energy.total());
    std::fprintf(summary.get(), "%s %.6f %.6f %.6f %lld %lld %.4f\n", m.argument.c_str(),
                 r.energy.back().energy.total() / E0, lo / E0, hi / E0, r.counters.newton_iterations,
                 r.counters.factorizations, r.wall_seconds);
    table.add_row({m.row->title, format_fixed(r.energy.back().energy.total() / E0, 5), format_fixed(lo / E0, 5),
                   format_fixed(hi / E0, 5)});
  }
  summary.commit();
  write_table_fragment(dir + "/energy_summary.md", table, command);
  return 0;
}
// [energy_study]

// The free particles' final positions of RK4 at h_ref: the reference of the accuracy studies. RK4 is explicit and
// shares no code with the implicit methods; at h_ref its error is far below theirs.
Vector reference_positions(const SceneParams& p, double T, double h_ref) {
  const Scene scene(p);
  ForceField field(scene);
  const auto rk4 = make_stepper("rk4", field);
  RunSettings run;
  run.dt = h_ref;
  run.t_end = T;
  run.stop = &interrupt_flag();
  const RunResult r = simulate(*rk4, run, false);
  throw_if_interrupted();
  if (r.status != RunStatus::ok) throw InputError("the RK4 reference failed: " + r.message);
  return r.x;
}

// One run of the accuracy studies, for the page's tables.
struct StudyRun {
  std::string title;
  NewtonVariant variant;
  double h, error, seconds;
  long long factorizations;
};

// [work_precision]
// Each method at the steps `hs` on `p` to T: the largest position error at T against `reference`, the processor
// time (best of `repeats`), and the work; one line per run in `path`, one gnuplot index per method and variant.
void work_precision(const SceneParams& p, double T, const std::vector<double>& hs, const Vector& reference,
                    const NewtonSettings& newton, const std::vector<NewtonVariant>& variants, const std::string& path,
                    int repeats, const std::vector<std::string>& only = {}, std::vector<StudyRun>* runs = nullptr) {
  OutputFile out(path);
  std::fprintf(out.get(), "# K = %g, D = %g, T = %g s; error = max |x - x_ref| over the free particles [m]\n"
               "# method newton h error processor_seconds newton_iterations factorizations rhs_evaluations\n",
               p.stiffness, p.damping, T);
  const Scene scene(p);
  ForceField field(scene);
  for (const NewtonVariant variant : variants) {
    NewtonSettings s = newton;
    s.variant = variant;
    for (const MethodChoice& m : study_methods(s)) {
      if (!only.empty() && std::find(only.begin(), only.end(), m.argument) == only.end()) continue;
      for (const double h : hs) {
        RunSettings run;
        run.dt = h;
        run.t_end = T;
        run.stop = &interrupt_flag();
        double best = INFINITY;
        RunResult r;
        for (int k = 0; k < repeats; ++k) {
          const std::unique_ptr<NewtonStepper> stepper = make_method(m, field);
          const double start = thread_cpu_seconds();  // the machine's other work does not count
          r = simulate(*stepper, run, false);
          // Stopped by a signal: the study's files are not written, so none lists the run as finished.
          throw_if_interrupted();
          best = std::min(best, thread_cpu_seconds() - start);
        }
        const double error =
            r.status == RunStatus::ok ? (r.x - reference).lpNorm<Eigen::Infinity>() : NAN;
        if (runs) runs->push_back({m.row->title, variant, h, error, best, r.counters.factorizations});
        std::fprintf(out.get(), "%s %s %.6g %.6e %.6f %lld %lld %lld\n", m.argument.c_str(),
                     newton_variant_name(variant), h, error, best, r.counters.newton_iterations,
                     r.counters.factorizations, r.counters.rhs_evaluations);
        std::fflush(out.get());
      }
      std::fprintf(out.get(), "\n\n");  // one gnuplot index per method and variant
    }
  }
  out.commit();
}
// [work_precision]

// How stiff the stiff cloth is for the study's steps: its fastest mode at rest (where the damper's matrix is D/K
// times the stiffness matrix, so that mode has the damping rate c = (D/K) omega_max^2), the size of h lambda over
// the steps, and the largest step at which explicit RK4 is stable on that mode. Written to `path` as a sentence.
void write_stiffness(const SceneParams& params, const std::vector<double>& hs, const std::string& path) {
  const Scene scene(params);
  ForceField field(scene);
  const double omega = fastest_rest_frequency(field);
  const double c = fastest_damping_rate(field, scene.initial_positions(), Vector::Zero(scene.dof_count()));
  // The roots of lambda^2 + c lambda + omega^2 = 0: a conjugate pair when c < 2 omega, else two real ones.
  const Complex root = std::sqrt(Complex(c * c / 4 - omega * omega, 0));
  const Complex lambda = -c / 2 - root;
  const ButcherTableau& rk4 = *find_method("rk4").tableau;
  const double rk4_limit = stability_limit_along(
      [&](double h) { return std::abs(stability_function(rk4, h * lambda)) <= 1 + 1e-12; }, 1.0);
  const auto [h_min, h_max] = std::minmax_element(hs.begin(), hs.end());
  write_text_fragment(
      path, "At rest the fastest mode of (K, D) = (" + format_number(params.stiffness) + ", " +
                format_number(params.damping) + ") has ω_max = " + format_number(omega, 4) +
                " rad/s and the damping rate c = " + format_number(c, 4) + " 1/s" +
                (c < 2 * omega ? ", less than 2ω_max: an underdamped oscillation, λ = " : ": overdamped, λ = ") +
                format_number(lambda.real(), 4) + (c < 2 * omega ? " ± " + format_number(std::abs(lambda.imag()), 4) + "i" : "") +
                " 1/s, |λ| = " + format_number(std::abs(lambda), 4) + " 1/s. Over the study's steps h|λ| runs from " +
                format_number(*h_min * std::abs(lambda), 2) + " (h = " + format_number(*h_min) + " s) to " +
                format_number(*h_max * std::abs(lambda), 2) + " (h = " + format_number(*h_max) +
                " s), and explicit RK4 is stable on this mode for every h up to " + format_number(rk4_limit, 3) + " s.\n");
}

// The chapter's studies: energy on the undamped cloth; observed orders on (200, 20) over T = 0.4 s; work against
// precision on the stiff cloth (5000, 20). --quick keeps the plots target fast (fewer steps, one timing).
int report_runs(const Options& opt, const NewtonSettings& newton, bool quick, const std::string& program,
                const std::string& command) {
  const std::string dir = opt.run.out_dir;
  // Every output of the studies, checked before the first run starts (a folder in the way is bad input).
  std::vector<std::string> outputs = {"energy_summary.dat", "orders.dat", "work_precision.dat", "methods.md",
                                      "energy_summary.md",  "orders.md",  "work_precision.md", "stiffness.md"};
  for (const MethodChoice& m : study_methods(newton))
    for (const std::string& name : run_output_names()) outputs.push_back("energy_" + m.argument + "/" + name);
  prepare_outputs(dir, outputs);
  // The page's table of the implicit rows of the registry: computed from their tableaus, not measured.
  write_text_fragment(dir + "/methods.md", implicit_method_table().markdown());
  if (const int status = energy_study(opt, newton, dir, program, command); status != 0) return status;

  SceneParams report = opt.scene;
  report.stiffness = 200;
  report.damping = 20;
  const double T = 0.4;
  const std::vector<double> hs = quick ? std::vector<double>{0.02, 0.01, 0.005}
                                       : std::vector<double>{0.04, 0.02, 0.01, 0.005, 0.0025, 0.00125};
  NewtonSettings tight = newton;
  tight.tolerance = 1e-12;  // Newton's error far below the truncation error: the orders are the methods'
  // The stage equations as they are: dampers frozen for the step change each stage by O(h^3), which would hide
  // every order above 2.
  tight.line_search = LineSearch::residual;
  // RK4 at h = 2e-5: its error (order 4) is below 1e-9 m here, far below every implicit method's.
  std::vector<StudyRun> orders;
  work_precision(report, T, hs, reference_positions(report, T, 2e-5), tight, {NewtonVariant::modified},
                 dir + "/orders.dat", 1, {}, &orders);
  // The observed order between consecutive steps, log2(e(2h) / e(h)), for each method (runs come h-descending).
  std::vector<std::string> header = {"(K, D) = (200, 20), T = 0.4 s"};
  for (const double h : hs) header.push_back(std::string("error at h = ") + format_number(h) + " [m]");
  header.emplace_back("observed order");
  std::string alignment(header.size(), 'r');  // the method's name left, the numbers right
  alignment[0] = 'l';
  MarkdownTable order_table(header, alignment);
  for (std::size_t k = 0; k + hs.size() <= orders.size(); k += hs.size()) {
    std::vector<std::string> row = {orders[k].title};
    for (std::size_t j = 0; j < hs.size(); ++j) row.push_back(format_number(orders[k + j].error, 2));
    const StudyRun& coarse = orders[k + hs.size() - 2];
    const StudyRun& fine = orders[k + hs.size() - 1];
    row.push_back(format_fixed(std::log(coarse.error / fine.error) / std::log(coarse.h / fine.h), 2));
    order_table.add_row(row);
  }
  write_table_fragment(dir + "/orders.md", order_table, command);

  SceneParams stiff = report;
  stiff.stiffness = 5000;
  write_stiffness(stiff, hs, dir + "/stiffness.md");
  // The figure shows the L-stable methods and BDF2; the others fail at the large steps (see the page).
  std::vector<StudyRun> stiff_runs;
  work_precision(stiff, T, hs, reference_positions(stiff, T, 2e-5), newton,
                 {NewtonVariant::full, NewtonVariant::modified}, dir + "/work_precision.dat", quick ? 1 : 3,
                 {"implicit_euler", "sdirk2", "sdirk3", "bdf2"}, &stiff_runs);
  // Full against modified Newton at the smallest step, where every method converges.
  const std::string stiff_scene = std::string("(K, D) = (5000, 20), T = 0.4 s, h = ") + format_number(hs.back()) + " s";
  MarkdownTable work_table({stiff_scene, "Newton", "error [m]", "time [s]", "factorizations"}, "llrrr");
  for (const StudyRun& r : stiff_runs)
    if (r.h == hs.back())
      work_table.add_row({r.title, newton_variant_name(r.variant), format_number(r.error, 2),
                          format_number(r.seconds, 2), std::to_string(r.factorizations)});
  write_table_fragment(dir + "/work_precision.md", work_table, command);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MethodChoice choice;
  NewtonFlags flags;
  bool want_report_runs = false, quick = false;
  CommandLine cli("ch09_implicit_runge_kutta",
                  "Chapter 9: a diagonally implicit Runge-Kutta method from its Butcher tableau, or BDF2, on the\n"
                  "report's cloth; each stage solved by Newton's method on M - h a_ii df/dv - (h a_ii)^2 df/dx.");
  std::string names;
  for (const Method* m : newton_methods()) names += m->name + ", ";
  std::string tableau_argument = "sdirk2";
  cli.add_value("--tableau", "NAME|FILE",
                "a registered implicit method (" + names + "default sdirk2) or a diagonally implicit tableau file",
                [&](const std::string& s) { tableau_argument = s; });
  cli.add_value("--tol", "TOL",
                "step control on the embedded error estimate, max |e| / (1 + |y|) <= TOL (embedded pairs only: "
                "trbdf2, esdirk32, esdirk43); --dt is then the first step",
                [&](const std::string& s) {
                  const double t = parse_number(s);
                  if (!(t > 0) || t >= 1) throw InputError("expected a number in (0, 1), got " + s);
                  choice.tol = t;
                });
  flags.add_to(cli);  // --newton, --linear-solver, --newton-tol, --newton-max-iter, --jacobian
  cli.add_switch("--report-runs",
                 "the chapter's studies: every method on the undamped cloth, orders on (K, D) = (200, 20) and work "
                 "against precision on (5000, 20) over T = 0.4 s (exit 0 even when a run fails)",
                 [&] { want_report_runs = true; });
  cli.add_switch("--quick", "with --report-runs: fewer step sizes and one timing per run (the plots target)",
                 [&] { quick = true; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    if (want_report_runs)
      refuse_unused(opt, "--report-runs", {"--tableau", "--tol", "--damping"},
                    "its studies run every registered method, at fixed steps, and set their own damping");
    else if (quick)
      throw InputError("--quick: only with --report-runs");
    {
      const std::optional<double> tol = choice.tol;
      choice = choose(tableau_argument);
      choice.tol = tol;
    }
    if (choice.tol && (choice.multistep() || !choice.tableau.has_embedded()))
      throw InputError("--tol: step control needs an embedded pair, and " + choice.argument +
                       " has no embedded weights: use --tableau trbdf2, or leave --tol out for fixed steps");
    // A controlled run's defaults (the chapter's measurements): modified Newton, the stage equations as they are
    // (frozen dampers would cost a third- or fourth-order pair its order), and Newton stopped at a tenth of the
    // error tolerance (Hairer & Wanner's kappa rule: the iteration's error well below the error controlled).
    if (choice.tol)
      flags.apply_defaults({NewtonVariant::modified, newton_kappa * *choice.tol, LineSearch::residual});
    // Newton's settings from their flags, with the one default rule for the Newton matrix (program/method_flags).
    choice.newton = flags.settings_for(Scene(opt.scene));
    choice.newton.estimate_test = choice.tol.has_value();  // a controlled run stops Newton on its error estimate
    // Newton's matrices and factors: the implicit methods' memory, beyond what parse checked for an explicit run.
    const long long particles = static_cast<long long>(opt.scene.grid.M) * opt.scene.grid.N;
    require_run_memory(opt.scene, opt.run, implicit_bytes_per_particle(particles));
    if (want_report_runs) {
      return report_runs(opt, choice.newton, quick, cli.program(), reader_command(argc, argv));
    }

    return run_cloth(opt.scene, opt.run, choice, cli.program());
  });
}
