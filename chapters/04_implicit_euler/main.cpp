// Chapter 4: implicit Euler on the report's cloth, each step solved by Newton's method on the analytic sparse
// Jacobian; Baraff and Witkin's one-iteration variant beside full Newton; the residuals of one stiff step.
#include "program/command_line.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/implicit_euler.hpp"
#include "integrators/simulate.hpp"
#include "program/interrupt.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"
#include "program/progress.hpp"
#include "program/run_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

using namespace cloth;

namespace {

const char* treatment_name(StiffnessTreatment t) {
  switch (t) {
    case StiffnessTreatment::exact: return "exact";
    case StiffnessTreatment::symmetric: return "symmetric";
    case StiffnessTreatment::definite: return "definite";
  }
  return "?";
}

struct Outcome {
  int status;
  RunResult result;
};

// One run of the cloth with `newton` (validated before anything was written), outputs in `dir`.
Outcome run_cloth(const SceneParams& params, RunSettings run, const NewtonSettings& newton, const std::string& dir,
                  const std::string& program) {
  const Scene scene(params);
  ForceField field(scene);
  ImplicitEuler stepper(field, newton);  // resolves the automatic solver choice
  run.out_dir = dir;
  run.progress = terminal_progress(program);
  RunResult result = simulate(stepper, run);
  const int status = finish_run(result, stepper, run, program,
                                {{"linear_solver", linear_solver_name(stepper.settings().solver)},
                                 {"jacobian", treatment_name(newton.treatment)},
                                 {"newton_tol", format_number(newton.tolerance, 10)},
                                 {"newton_max_iter", std::to_string(newton.max_iterations)}});
  if (result.steps > 0)
    std::printf("  Newton iterations per step: %.3f (%lld in %lld steps), %lld factorizations\n",
                static_cast<double>(result.counters.newton_iterations) / static_cast<double>(result.steps),
                result.counters.newton_iterations, result.steps, result.counters.factorizations);
  return {status, std::move(result)};
}

// [stiff_step_residuals]
// The residual |r|_inf after each Newton iteration of the first step of the report scene at K = 1e5 N/m,
// h = 0.01 s (h omega_max ~ 10): exact Jacobian, sparse LU, tolerance tight enough to watch the sequence reach
// rounding. Writes residuals.dat: iteration k, |r_k|, |r_k| / |r_{k-1}|^2.
void stiff_step_residuals(const SceneParams& report_scene, const std::string& dir) {
  SceneParams p = report_scene;
  p.stiffness = 1e5;
  p.damping = 0;
  const Scene scene(p);
  ForceField field(scene);
  NewtonSettings newton;
  newton.solver = LinearSolverKind::lu;
  newton.treatment = StiffnessTreatment::exact;
  newton.tolerance = 1e-14;
  newton.max_iterations = 30;
  ImplicitEuler stepper(field, newton);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  stepper.step(0.01, x, v);  // if it fails the history still shows how far it got
  const std::vector<double>& r = stepper.residual_history();
  OutputFile file(dir + "/residuals.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# first step of the report scene, K = 1e5, D = 0, h = 0.01, exact Jacobian, LU\n");
  std::fprintf(out, "# k |r_k|_inf |r_k|/|r_(k-1)|^2\n");
  std::printf("stiff step (K = 1e5, h = 0.01, exact Jacobian, LU): |r_k|_inf =");
  for (std::size_t k = 0; k < r.size(); ++k) {
    std::fprintf(out, "%zu %.6e %.6e\n", k, r[k], k ? r[k] / (r[k - 1] * r[k - 1]) : NAN);
    std::printf(" %.3g", r[k]);
  }
  std::printf("\n");
  file.commit();
}
// [stiff_step_residuals]

// Newton iterations of every step for one setting, stepping by hand so that each step's count is seen:
// iterations.dat gets t and the count; a failed step ends the file with its count and the step's time.
void iterations_per_step(const SceneParams& params, const RunSettings& run, const NewtonSettings& newton,
                         const std::string& path) {
  const Scene scene(params);
  ForceField field(scene);
  ImplicitEuler stepper(field, newton);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  OutputFile file(path);
  std::FILE* out = file.get();
  std::fprintf(out, "# t newton_iterations final_residual (K = %g, D = %g, h = %g, jacobian %s)\n", params.stiffness,
               params.damping, run.dt, treatment_name(newton.treatment));
  const auto steps = std::llround(run.t_end / run.dt);
  for (long long n = 1; n <= steps && interrupt_signal() == 0; ++n) {
    const long long before = stepper.counters().newton_iterations;
    const bool ok = stepper.step(run.dt, x, v);
    std::fprintf(out, "%.10g %lld %.6e\n", static_cast<double>(n) * run.dt,
                 stepper.counters().newton_iterations - before, stepper.residual_history().back());
    if (!ok) break;
  }
  file.commit();  // whole up to the last step taken, when interrupted too
  throw_if_interrupted();
}

// The report's three (K, D), each run with full Newton and with one iteration, in subfolders of --out.
struct Config {
  double K, D;
};
constexpr Config report_configs[] = {{50, 0}, {200, 0}, {200, 20}};

std::string report_folder(const char* variant, const Config& c) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_K%g_D%g", variant, c.K, c.D);
  return name;
}

std::vector<std::string> report_outputs() {
  std::vector<std::string> names = {"comparison.dat", "residuals.dat", "iterations_symmetric.dat",
                                    "iterations_definite.dat"};
  for (const Config& c : report_configs)
    for (const char* variant : {"full", "one"})
      for (const std::string& file : run_output_names()) names.push_back(report_folder(variant, c) + "/" + file);
  return names;
}

// The report's three (K, D) with full Newton and with one Newton iteration, the stiff step's residuals, and the
// definite (Choi & Ko) matrix against the symmetric one at K = 50.
// `newton_for(K, D)` gives the settings of the full-Newton run at (K, D), as main checked them before any run.
int report_runs(const Options& opt, const std::function<NewtonSettings(double, double)>& newton_for,
                const NewtonSettings& newton, const std::string& program) {
  const std::string dir = opt.run.out_dir;
  OutputFile summary_file(dir + "/comparison.dat");
  std::FILE* summary = summary_file.get();
  std::fprintf(summary, "# K D newton_per_step_full newton_per_step_one factorizations_full factorizations_one "
                        "wall_full wall_one E_final_full E_final_one max_position_difference\n");
  for (const Config& c : report_configs) {
    SceneParams p = opt.scene;
    p.stiffness = c.K;
    p.damping = c.D;
    const NewtonSettings full = newton_for(c.K, c.D);
    const Outcome a = run_cloth(p, opt.run, full, dir + "/" + report_folder("full", c), program);
    if (a.status >= 128) return a.status;  // interrupted: the run said so; comparison.dat is not written
    NewtonSettings one = full;
    one.max_iterations = 1;
    const Outcome b = run_cloth(p, opt.run, one, dir + "/" + report_folder("one", c), program);
    if (b.status >= 128) return b.status;
    const double diff = a.result.t == b.result.t ? (a.result.x - b.result.x).lpNorm<Eigen::Infinity>() : NAN;
    const auto per_step = [](const RunResult& r) {
      return r.steps ? static_cast<double>(r.counters.newton_iterations) / static_cast<double>(r.steps) : 0.0;
    };
    std::fprintf(summary, "%g %g %.4f %.4f %lld %lld %.4f %.4f %.8g %.8g %.4e\n", c.K, c.D, per_step(a.result),
                 per_step(b.result), a.result.counters.factorizations, b.result.counters.factorizations,
                 a.result.wall_seconds, b.result.wall_seconds, a.result.energy.back().energy.total(),
                 b.result.energy.back().energy.total(), diff);
    std::printf("K = %g, D = %g: full Newton %.3f iterations/step, one iteration: largest position difference at "
                "t = %g s: %.4g m\n", c.K, c.D, per_step(a.result), a.result.t, diff);
  }
  summary_file.commit();
  stiff_step_residuals(opt.scene, dir);
  throw_if_interrupted();
  SceneParams p = opt.scene;
  p.stiffness = 50;
  p.damping = 0;
  NewtonSettings symmetric = newton, definite = newton;
  symmetric.treatment = StiffnessTreatment::symmetric;
  definite.treatment = StiffnessTreatment::definite;
  iterations_per_step(p, opt.run, symmetric, dir + "/iterations_symmetric.dat");
  iterations_per_step(p, opt.run, definite, dir + "/iterations_definite.dat");
  return 0;
}

// [jacobian_default]
// Without --jacobian, the most exact matrix the chosen solver can take: CG needs a symmetric positive definite
// matrix, LDL^T a symmetric one (the damper's d/dx breaks symmetry), LDU and LU take the exact one. An explicit
// incompatible choice is refused by validate(NewtonSettings) with exit status 2.
StiffnessTreatment default_treatment(LinearSolverKind solver, bool damped) {
  if (solver == LinearSolverKind::cg) return StiffnessTreatment::definite;
  if (solver == LinearSolverKind::ldlt && damped) return StiffnessTreatment::symmetric;
  return StiffnessTreatment::exact;
}
// [jacobian_default]

}  // namespace

int main(int argc, char** argv) {
  NewtonSettings newton;
  std::optional<StiffnessTreatment> jacobian;
  bool want_report_runs = false;
  CommandLine cli("ch04_implicit_euler",
                  "Chapter 4: implicit Euler on the report's cloth, each step solved by Newton's method on the\n"
                  "analytic sparse Jacobian J = M - h df/dv - h^2 df/dx.");
  cli.add_value("--linear-solver", "ldlt|ldu|cg|lu",
                "block LDL^T, block LDU, block-Jacobi-preconditioned CG, or Eigen's pivoting sparse LU (default: ldu "
                "for the exact Jacobian of a damped cloth, ldlt otherwise)",
                [&](const std::string& s) {
                  if (s == "ldlt") newton.solver = LinearSolverKind::ldlt;
                  else if (s == "ldu") newton.solver = LinearSolverKind::ldu;
                  else if (s == "cg") newton.solver = LinearSolverKind::cg;
                  else if (s == "lu") newton.solver = LinearSolverKind::lu;
                  else throw InputError("unknown solver '" + s + "': expected ldlt, ldu, cg or lu");
                });
  cli.add_value("--newton-tol", "TOL", "Newton's stopping tolerance on |dv| and |r| (default 1e-8)",
                [&](const std::string& s) {
                  const double t = parse_number(s);
                  if (!(t > 0) || t >= 1) throw InputError("expected a number in (0, 1), got " + s);
                  newton.tolerance = t;
                });
  cli.add_value("--newton-max-iter", "N",
                "Newton iterations before a step fails (default 20); 1 is Baraff & Witkin's one-iteration step",
                [&](const std::string& s) {
                  const long long n = parse_integer(s);
                  if (n < 1 || n > 1000) throw InputError("expected a whole number from 1 to 1000, got " + s);
                  newton.max_iterations = static_cast<int>(n);
                });
  cli.add_value("--jacobian", "exact|symmetric|definite",
                "the Newton matrix's df/dx: exact (default), symmetric (drops the damper's d/dx) or definite "
                "(Choi & Ko 2002; the default with cg)",
                [&](const std::string& s) {
                  if (s == "exact") jacobian = StiffnessTreatment::exact;
                  else if (s == "symmetric") jacobian = StiffnessTreatment::symmetric;
                  else if (s == "definite") jacobian = StiffnessTreatment::definite;
                  else throw InputError("unknown Jacobian '" + s + "': expected exact, symmetric or definite");
                });
  cli.add_switch("--report-runs",
                 "the report's (K, D) = (50,0), (200,0), (200,20) with full and one-iteration Newton, a stiff step's "
                 "residuals and the definite matrix at K = 50 (the chapter's figures; exit 0 even when a run fails)",
                 [&] { want_report_runs = true; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const auto particles = static_cast<long long>(opt.scene.grid.M) * opt.scene.grid.N;
    // The settings of a run at (K, D): the Newton matrix the solver takes unless --jacobian chose one.
    const auto newton_for = [&](double K, double D) {
      SceneParams p = opt.scene;
      p.stiffness = K;
      p.damping = D;
      NewtonSettings s = newton;
      s.treatment = jacobian ? *jacobian : default_treatment(newton.solver, Scene(p).has_damping());
      validate(s, Scene(p));
      return s;
    };
    if (!want_report_runs) {
      const NewtonSettings settings = newton_for(opt.scene.stiffness, opt.scene.damping);
      require_run_memory(opt.scene, opt.run, implicit_bytes_per_particle(particles));
      prepare_outputs(opt.run.out_dir, run_output_names(), report_outputs());
      return run_cloth(opt.scene, opt.run, settings, opt.run.out_dir, cli.program()).status;
    }
    // Every run of --report-runs is checked, with the values it uses, before the first one starts.
    for (const Config& c : report_configs) {
      SceneParams p = opt.scene;
      p.stiffness = c.K;
      p.damping = c.D;
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
    prepare_outputs(opt.run.out_dir, report_outputs(), run_output_names());
    return report_runs(opt, newton_for, newton, cli.program());
  });
}
