// Chapter 4: implicit Euler on the report's cloth, each step solved by Newton's method on the analytic sparse
// Jacobian; Baraff and Witkin's one-iteration variant beside full Newton; the residuals of one stiff step.
#include "program/command_line.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "model/report_cases.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/limits.hpp"
#include "program/method_flags.hpp"
#include "program/output.hpp"
#include "program/progress.hpp"
#include "program/run_outputs.hpp"
#include "potential_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

using namespace cloth;

namespace {

struct Outcome {
  int status;
  RunResult result;
  std::string method;  // the stepper's name, as run.txt and the failure message give it
};

// One run of the cloth with `newton` (validated before anything was written), outputs in `dir`.
Outcome run_cloth(const SceneParams& params, RunSettings run, const NewtonSettings& newton, const std::string& dir,
                  const std::string& program) {
  const Scene scene(params);
  ForceField field(scene);
  const auto made = make_newton_stepper("implicit_euler", field, {newton});  // resolves the automatic solver choice
  NewtonStepper& stepper = *made;
  run.out_dir = dir;
  run.progress = terminal_progress(program);
  RunResult result = simulate(stepper, run);
  const int status = finish_run(result, stepper, run, program,
                                {{"newton", newton_variants().name(newton.variant)},
                                 {"linear_solver", linear_solvers().name(stepper.settings().solver)},
                                 {"jacobian", stiffness_treatments().name(newton.treatment)},
                                 {"newton_tol", format_number(newton.tolerance, 10)},
                                 {"newton_max_iter", std::to_string(newton.max_iterations)},
                                 {"line_search", line_searches().name(newton.line_search)}});
  if (result.steps > 0)
    std::printf("  Newton iterations per step: %.3f (%lld in %lld steps), %lld factorizations\n",
                result.newton_iterations_per_step(),
                result.counters.newton_iterations, result.steps, result.counters.factorizations);
  return {status, std::move(result), stepper.name()};
}

// `newton` as full Newton on `solver` with the Jacobian `treatment`: the settings of the chapter's measured runs,
// each of which fixes what it compares, whatever the command line chose.
NewtonSettings full_newton(NewtonSettings newton, LinearSolverKind solver, StiffnessTreatment treatment) {
  newton.solver = solver;
  newton.treatment = treatment;
  newton.variant = NewtonVariant::full;
  return newton;
}

// [stiff_step_residuals]
// The residual |r|_inf after each Newton iteration of the first step of the report scene at K = 1e5 N/m,
// h = 0.01 s (h omega_max ~ 10): exact Jacobian, sparse LU, tolerance tight enough to watch the sequence reach
// rounding.
std::vector<double> stiff_step_residuals(const SceneParams& report_scene) {
  const Scene scene(with_K_and_D(report_scene, 1e5, 0));
  ForceField field(scene);
  NewtonSettings newton;
  newton.solver = LinearSolverKind::lu;
  newton.treatment = StiffnessTreatment::exact;
  newton.tolerance = 1e-14;
  newton.max_iterations = 30;
  const auto made = make_newton_stepper("implicit_euler", field, {newton});
  NewtonStepper& stepper = *made;
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  stepper.step(0.01, x, v);  // if it fails the history still shows how far it got
  return stepper.residual_history();
}
// [stiff_step_residuals]

// residuals.dat for the figure (iteration k, |r_k|, |r_k| / |r_{k-1}|^2), and the page's table of the same.
void write_stiff_step(const std::vector<double>& r, const std::string& dir, const std::string& command) {
  OutputFile file(dir + "/residuals.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# first step of the report scene, K = 1e5, D = 0, h = 0.01, exact Jacobian, LU\n");
  std::fprintf(out, "# k |r_k|_inf |r_k|/|r_(k-1)|^2   (? : no ratio at k = 0, gnuplot's missing value)\n");
  std::printf("stiff step (K = 1e5, h = 0.01, exact Jacobian, LU): |r_k|_inf =");
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (k == 0) std::fprintf(out, "%zu %.6e ?\n", k, r[k]);
    else std::fprintf(out, "%zu %.6e %.6e\n", k, r[k], r[k] / (r[k - 1] * r[k - 1]));
    std::printf(" %.3g", r[k]);
  }
  std::printf("\n");
  file.commit();
  // The table stops at the rounding floor: the first iterate that no later one improves tenfold. The iterates
  // after it only wander around the floor, and are summed up in one row.
  MarkdownTable table({"Newton iteration k", "residual r_k (max norm) [N s]", "r_k / r_(k-1)^2"}, "rrr");
  std::size_t floor = 0;
  while (floor + 1 < r.size() && *std::min_element(r.begin() + static_cast<std::ptrdiff_t>(floor) + 1, r.end()) <
                                     0.1 * r[floor])
    ++floor;
  for (std::size_t k = 0; k <= floor && k < r.size(); ++k)
    table.add_row({std::to_string(k), format_number(r[k], 3),
                   k == 0 ? "" : k == floor ? "(rounding floor)" : format_number(r[k] / (r[k - 1] * r[k - 1]), 2)});
  if (floor + 1 < r.size()) {
    const auto [low, high] = std::minmax_element(r.begin() + static_cast<std::ptrdiff_t>(floor) + 1, r.end());
    table.add_row({std::to_string(floor + 1) + " to " + std::to_string(r.size() - 1),
                   format_number(*low, 2) + " to " + format_number(*high, 2), "(rounding floor)"});
  }
  write_table_fragment(dir + "/stiff_step.md", table, command);
}

// What one setting's Newton iterations came to, over the steps it took.
struct IterationSummary {
  std::string solver;                  // the linear solver the setting resolved to
  long long accepted = 0;              // steps accepted
  long long iterations = 0;            // Newton iterations in the accepted steps
  long long most = 0;                  // most iterations in one accepted step
  std::optional<std::string> failure;  // the failed step, when one failed
};

// Newton iterations of every step for one setting, stepping by hand so that each step's count is seen:
// iterations.dat gets t and the count; a failed step ends the file with its count and the step's time.
IterationSummary iterations_per_step(const SceneParams& params, const RunSettings& run, const NewtonSettings& newton,
                                     const std::string& path) {
  const Scene scene(params);
  ForceField field(scene);
  const auto made = make_newton_stepper("implicit_euler", field, {newton});
  NewtonStepper& stepper = *made;
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  OutputFile file(path);
  std::FILE* out = file.get();
  std::fprintf(out, "# t newton_iterations final_residual (K = %g, D = %g, h = %g, jacobian %s)\n", params.stiffness,
               params.damping, run.dt, stiffness_treatments().name(newton.treatment));
  IterationSummary summary;
  summary.solver = linear_solvers().name(stepper.settings().solver);
  const auto steps = std::llround(run.t_end / run.dt);
  for (long long n = 1; n <= steps && interrupt_signal() == 0; ++n) {
    const long long before = stepper.counters().newton_iterations;
    const bool ok = stepper.step(run.dt, x, v);
    const long long iterations = stepper.counters().newton_iterations - before;
    const double t = static_cast<double>(n) * run.dt;
    std::fprintf(out, "%.10g %lld %.6e\n", t, iterations, stepper.residual_history().back());
    if (!ok) {
      summary.failure = "fails at step " + std::to_string(n) + ", t = " + format_number(t) + " s: " +
                        std::to_string(iterations) + " iterations, residual " +
                        format_number(stepper.residual_history().back(), 2);
      break;
    }
    ++summary.accepted;
    summary.iterations += iterations;
    summary.most = std::max(summary.most, iterations);
  }
  file.commit();  // whole up to the last step taken, when interrupted too
  throw_if_interrupted();
  return summary;
}

// The report's three (K, D), each run with full Newton and with one iteration, in subfolders of --out.
std::string report_folder(const char* variant, const ReportCase& c) { return std::string(variant) + "_" + c.name(); }

// The single runs behind the page's other measurements, each in a subfolder: the definite matrix's failure, the
// stiff cloth at a large step, and conjugate gradients.
const char* const measured_run_folders[] = {"definite_K50_D0", "stiff_K100000_h0.1", "cg_K50_D0"};

// What --report-runs writes into --out, declared once (program/output_spec.hpp).
OutputList report_outputs() {
  const OutputKind figure = OutputKind::figure_input, fragment = OutputKind::fragment, data = OutputKind::data;
  OutputList files = {
      {"comparison.dat", data, "full Newton against one iteration at each (K, D): iterations, energies"},
      {"residuals.dat", figure, "the residual of each Newton iteration on one stiff step"},
      {"iterations_symmetric.dat", figure, "Newton iterations per step, symmetric Hessian, K = 50, D = 0"},
      {"iterations_definite.dat", figure, "Newton iterations per step, definite matrix, K = 50, D = 0"},
      {"iterations_symmetric_K200_D20.dat", data, "Newton iterations per step, symmetric Jacobian, K = 200, D = 20"},
      {"iterations_exact_K200_D20.dat", data, "Newton iterations per step, exact Jacobian, K = 200, D = 20"},
      {"report_runs.md", fragment, "full Newton against one iteration at the report's (K, D)"},
      {"stiff_step.md", fragment, "the residuals of one stiff step and their ratios"},
      {"jacobian_treatments.md", fragment, "what each Newton matrix costs in iterations"},
      {"definite_failure.txt", fragment, "the transcript of the definite matrix's failed run"},
      {"stiff_large_step.md", fragment, "the stiff cloth at a large step"},
      {"cg_run.md", fragment, "the run with conjugate gradients"},
      {"rk4_agreement.md", fragment, "implicit Euler's distance from RK4 at three steps"},
      {"rk4_halving_ratio.md", fragment, "what halving h divides that distance by"},
      {"flat_step.md", fragment, "the residual search's history on the flat curtain"},
      {"curtain_runs.md", fragment, "the curtain under the minimising Newton step"},
      {"frozen_dampers.md", fragment, "dampers frozen at the start of the step against at the free flight"}};
  for (const ReportCase& c : report_cases)
    for (const char* variant : {"full", "one"}) files = files + run_output_specs(report_folder(variant, c), {"energy.dat"});
  for (const char* folder : measured_run_folders) files = files + run_output_specs(folder);
  return files;
}

// What the Newton matrix's treatment costs: the exact (= symmetric) Hessian against the definite matrix on the
// undamped report scene, and the exact Jacobian against the symmetric one with damping. All four solve the stage
// equation as it is, with the residual search: minimising, the frozen damper has no d/dx to drop.
void treatments_table(const Options& opt, const NewtonSettings& newton, const IterationSummary& sym,
                      const IterationSummary& def, const std::string& dir, const std::string& command) {
  MarkdownTable table({"K, D", "Jacobian", "solver", "Newton iterations per step", "most in one step", "outcome"},
                      "llrrrl");
  const auto add = [&](const std::string& KD, const std::string& jacobian, const IterationSummary& s) {
    const double mean = s.accepted ? static_cast<double>(s.iterations) / static_cast<double>(s.accepted) : 0.0;
    table.add_row({KD, jacobian, s.solver, format_fixed(mean, 2), std::to_string(s.most),
                   s.failure ? "**" + *s.failure + "**" : "finishes the " + format_number(opt.run.t_end) + " s"});
  };
  add("50, 0", "symmetric (= exact here)", sym);
  add("50, 0", "definite", def);
  const SceneParams damped = with_K_and_D(opt.scene, 200, 20);
  // Each with the solver its matrix calls for.
  NewtonSettings exact = full_newton(newton, LinearSolverKind::automatic, StiffnessTreatment::exact);
  NewtonSettings symmetric = full_newton(newton, LinearSolverKind::automatic, StiffnessTreatment::symmetric);
  exact.line_search = symmetric.line_search = LineSearch::residual;
  add("200, 20", "symmetric",
      iterations_per_step(damped, opt.run, symmetric, dir + "/iterations_symmetric_K200_D20.dat"));
  add("200, 20", "exact", iterations_per_step(damped, opt.run, exact, dir + "/iterations_exact_K200_D20.dat"));
  write_table_fragment(dir + "/jacobian_treatments.md", table, command);
}

// The run a reader gets with `--jacobian definite --line-search residual`, and what it prints when its Newton
// iteration stalls.
int definite_failure_transcript(const SceneParams& params, const RunSettings& run, NewtonSettings definite,
                                const std::string& dir, const std::string& program) {
  definite.line_search = LineSearch::residual;
  const Outcome o = run_cloth(params, run, definite, dir + "/" + measured_run_folders[0], program);
  if (o.status >= 128) return o.status;
  std::string text = "$ build/bin/" + program + " --jacobian definite --line-search residual\n";
  if (o.status != 0) text += program + ": " + o.method + " " + o.result.message + "\n";
  write_text_fragment(dir + "/definite_failure.txt", text + "$ echo $?\n" + std::to_string(o.status) + "\n");
  return 0;
}

// Numbers the page quotes in its prose, each in a sentence of its own (Doxygen includes a file as a separate
// word, so the page includes each at the end of a line): the stiff cloth at a large step, which the line search
// makes possible, and conjugate gradients on the report scene.
int measured_sentences(const Options& opt, const NewtonSettings& newton, const std::string& dir,
                       const std::string& program) {
  RunSettings large_step = opt.run;
  large_step.dt = 0.1;
  const Outcome a = run_cloth(with_K_and_D(opt.scene, 1e5, 0), large_step,
                              full_newton(newton, LinearSolverKind::automatic, StiffnessTreatment::exact),
                              dir + "/" + measured_run_folders[1], program);
  if (a.status >= 128) return a.status;
  write_text_fragment(dir + "/stiff_large_step.md",
                      "At h = " + format_number(large_step.dt) + " s it takes " + std::to_string(a.result.steps) +
                          " steps to t = " + format_number(a.result.t) + " s, with " +
                          format_number(a.result.newton_iterations_per_step(), 2) + " Newton iterations per step.");
  RunSettings short_run = opt.run;
  short_run.t_end = 0.3;
  const Outcome b = run_cloth(with_K_and_D(opt.scene, 50, 0), short_run,
                              full_newton(newton, LinearSolverKind::cg, StiffnessTreatment::definite),
                              dir + "/" + measured_run_folders[2], program);
  if (b.status >= 128) return b.status;
  const StepCounters& n = b.result.counters;
  const double cg_per_solve =
      n.newton_iterations ? static_cast<double>(n.cg_iterations) / static_cast<double>(n.newton_iterations) : 0.0;
  write_text_fragment(dir + "/cg_run.md",
                      "On the report scene (K = 50, D = 0) its " + std::to_string(b.result.steps) + " steps to t = " +
                          format_number(b.result.t) + " s took " + format_number(b.result.newton_iterations_per_step(), 2) +
                          " Newton iterations per step and " + format_number(cg_per_solve, 2) +
                          " CG iterations per solve, " + std::to_string(n.cg_iterations) + " in all.");
  return 0;
}

// Implicit Euler against RK4 on the damped report scene (K = 200, D = 20) to t = 1 s: RK4 at h = 1e-3 is the
// reference (its own error, estimated from RK4 at h/2, is far smaller), and implicit Euler's distance from it
// should halve with h, the method being of first order. Distances are max norms over all coordinates.
void agreement_with_rk4(const SceneParams& report_scene, RunSettings run, const NewtonSettings& newton,
                        const std::string& dir, const std::string& command) {
  const SceneParams p = with_K_and_D(report_scene, 200, 20);
  run.t_end = 1;
  const Scene scene(p);
  ForceField field(scene);
  const auto run_with = [&](Stepper& stepper, double h) {
    run.dt = h;
    RunResult r = simulate(stepper, run, false);
    throw_if_interrupted();
    if (r.status != RunStatus::ok) throw std::runtime_error(stepper.name() + " " + r.message);
    return r;
  };
  const auto rk4 = make_stepper("rk4", field);
  const double steps[2] = {1e-3, 5e-4};
  const RunResult reference = run_with(*rk4, steps[0]);
  const RunResult rk4_half = run_with(*rk4, steps[1]);
  MarkdownTable table({"K = 200, D = 20, to t = 1 s", "largest position difference from RK4 at h = 0.001 [m]",
                       "Newton iterations per step"}, "lrr");
  const NewtonSettings exact = full_newton(newton, LinearSolverKind::automatic, StiffnessTreatment::exact);
  double distance[2];
  for (int k = 0; k < 2; ++k) {
    const auto implicit = make_stepper("implicit_euler", field, {exact});
    const RunResult r = run_with(*implicit, steps[k]);
    distance[k] = (r.x - reference.x).lpNorm<Eigen::Infinity>();
    table.add_row({"implicit Euler, h = " + format_number(steps[k]), format_number(distance[k], 3),
                   format_fixed(r.newton_iterations_per_step(), 2)});
  }
  const double rk4_difference = (rk4_half.x - reference.x).lpNorm<Eigen::Infinity>();
  table.add_row({"RK4, h = " + format_number(steps[1]), format_number(rk4_difference, 2), ""});
  write_table_fragment(dir + "/rk4_agreement.md", table, command);
  write_text_fragment(dir + "/rk4_halving_ratio.md", "Halving h divides implicit Euler's distance from RK4 by " +
                                                         format_number(distance[0] / distance[1], 3) + ".");
}

// The report's three (K, D) with full Newton and with one Newton iteration, the stiff step's residuals, and the
// definite (Choi & Ko) matrix against the symmetric one at K = 50.
// `newton_for(K, D)` gives the settings of the full-Newton run at (K, D), as main checked them before any run.
int report_runs(const Options& opt, const std::function<NewtonSettings(double, double)>& newton_for,
                const NewtonSettings& newton, const std::string& program, const std::string& command) {
  const std::string dir = opt.run.out_dir;
  OutputFile summary_file(dir + "/comparison.dat");
  std::FILE* summary = summary_file.get();
  std::fprintf(summary, "# K D newton_per_step_full newton_per_step_one factorizations_full factorizations_one "
                        "wall_full wall_one E_final_full E_final_one max_position_difference\n");
  MarkdownTable table({"K, D", "Newton iterations per step, full", "factorizations full / one", "E(2 s) full [J]",
                       "E(2 s) one iteration [J]", "energy lost by 2 s, full",
                       "largest position difference at 2 s [m]"},
                      "lrrrrrr");
  for (const ReportCase& c : report_cases) {
    const SceneParams p = with_case(opt.scene, c);
    const NewtonSettings full = newton_for(c.K, c.D);
    const Outcome a = run_cloth(p, opt.run, full, dir + "/" + report_folder("full", c), program);
    if (a.status >= 128) return a.status;  // interrupted: the run said so; comparison.dat is not written
    NewtonSettings one = full;
    one.variant = NewtonVariant::one;
    const Outcome b = run_cloth(p, opt.run, one, dir + "/" + report_folder("one", c), program);
    if (b.status >= 128) return b.status;
    const double diff = a.result.t == b.result.t ? (a.result.x - b.result.x).lpNorm<Eigen::Infinity>() : NAN;
    std::fprintf(summary, "%g %g %.4f %.4f %lld %lld %.4f %.4f %.8g %.8g %.4e\n", c.K, c.D, a.result.newton_iterations_per_step(),
                 b.result.newton_iterations_per_step(), a.result.counters.factorizations, b.result.counters.factorizations,
                 a.result.wall_seconds, b.result.wall_seconds, a.result.energy.back().energy.total(),
                 b.result.energy.back().energy.total(), diff);
    std::printf("K = %g, D = %g: full Newton %.3f iterations/step, one iteration: largest position difference at "
                "t = %g s: %.4g m\n", c.K, c.D, a.result.newton_iterations_per_step(), a.result.t, diff);
    const double E0 = a.result.energy.front().energy.total(), E_full = a.result.energy.back().energy.total();
    table.add_row({format_number(c.K) + ", " + format_number(c.D), format_fixed(a.result.newton_iterations_per_step(), 2),
                   std::to_string(a.result.counters.factorizations) + " / " +
                       std::to_string(b.result.counters.factorizations),
                   format_fixed(E_full, 2), format_fixed(b.result.energy.back().energy.total(), 2),
                   format_number(100 * (E0 - E_full) / E0, 2) + "%", format_number(diff, 2)});
  }
  summary_file.commit();
  write_table_fragment(dir + "/report_runs.md", table, command);
  write_stiff_step(stiff_step_residuals(opt.scene), dir, command);
  throw_if_interrupted();
  const SceneParams p = with_K_and_D(opt.scene, 50, 0);
  NewtonSettings symmetric = newton, definite = newton;
  symmetric.treatment = StiffnessTreatment::symmetric;
  definite.treatment = StiffnessTreatment::definite;
  symmetric.line_search = definite.line_search = LineSearch::residual;
  const IterationSummary sym = iterations_per_step(p, opt.run, symmetric, dir + "/iterations_symmetric.dat");
  const IterationSummary def = iterations_per_step(p, opt.run, definite, dir + "/iterations_definite.dat");
  treatments_table(opt, newton, sym, def, dir, command);
  if (const int status = definite_failure_transcript(p, opt.run, definite, dir, program)) return status;
  if (const int status = measured_sentences(opt, newton, dir, program)) return status;
  agreement_with_rk4(opt.scene, opt.run, newton, dir, command);
  ch04::flat_step_history(opt.scene, dir, command);
  ch04::curtain_runs(opt.scene, opt.run, dir, command);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  NewtonFlags flags;
  bool want_report_runs = false;
  CommandLine cli("ch04_implicit_euler",
                  "Chapter 4: implicit Euler on the report's cloth, each step solved by Newton's method on the\n"
                  "analytic sparse Jacobian J = M - h df/dv - h^2 df/dx.");
  flags.add_to(cli);  // --newton, --linear-solver, --newton-tol, --newton-max-iter, --jacobian
  cli.add_switch("--report-runs",
                 "the report's (K, D) = (50,0), (200,0), (200,20) with full and one-iteration Newton, a stiff step's "
                 "residuals and the definite matrix at K = 50 (the chapter's figures; exit 0 even when a run fails)",
                 [&] { want_report_runs = true; });
  cli.declare_outputs([&](const Options&) { return want_report_runs ? report_outputs() : run_output_specs(); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const NewtonSettings& newton = flags.given();
    const auto particles = static_cast<long long>(opt.scene.grid.M) * opt.scene.grid.N;
    // The settings of a run at (K, D): the Newton matrix the solver takes unless --jacobian chose one.
    const auto newton_for = [&](double K, double D) {
      return flags.settings_for(Scene(with_K_and_D(opt.scene, K, D)));
    };
    if (!want_report_runs) {
      const NewtonSettings settings = newton_for(opt.scene.stiffness, opt.scene.damping);
      require_run_memory(opt.scene, opt.run, implicit_bytes_per_particle(particles));
      prepare_outputs(opt.run.out_dir, run_output_specs(), report_outputs());
      return run_cloth(opt.scene, opt.run, settings, opt.run.out_dir, cli.program()).status;
    }
    // Every run of --report-runs is checked, with the values it uses, before the first one starts.
    for (const ReportCase& c : report_cases) {
      const SceneParams p = with_case(opt.scene, c);
      try {
        newton_for(c.K, c.D);
      } catch (const InputError& e) {
        throw InputError(std::string(e.what()) + " (--report-runs runs K = " + format_number(c.K) +
                         ", D = " + format_number(c.D) + ")");
      }
      require_representable(p, opt.run);
    }
    if (newton.solver == LinearSolverKind::cg)
      throw InputError("--linear-solver cg: --report-runs compares the symmetric and the definite Newton matrix, and "
                       "cg takes only the definite one: expected ldlt, ldu or lu");
    require_run_memory(opt.scene, opt.run, implicit_bytes_per_particle(particles), "--frames", 2);
    prepare_outputs(opt.run.out_dir, report_outputs(), run_output_specs());
    return report_runs(opt, newton_for, newton, cli.program(), reader_command(argc, argv));
  });
}
