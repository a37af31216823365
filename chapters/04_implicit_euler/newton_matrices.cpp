// What the Newton matrix's treatment costs: Newton iterations per step with the exact (symmetric) Hessian against
// the definite (Choi and Ko) matrix, the exact Jacobian against the symmetric one with damping, and the run in
// which the definite matrix's iteration stalls.
#include "report.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace ch04 {

using namespace cloth;

namespace {

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

}  // namespace

int newton_matrices(const Study& study) {
  const SceneParams p = with_K_and_D(study.opt.scene, 50, 0);
  NewtonSettings symmetric = study.newton, definite = study.newton;
  symmetric.treatment = StiffnessTreatment::symmetric;
  definite.treatment = StiffnessTreatment::definite;
  symmetric.line_search = definite.line_search = LineSearch::residual;
  const IterationSummary sym = iterations_per_step(p, study.opt.run, symmetric, study.dir + "/iterations_symmetric.dat");
  const IterationSummary def = iterations_per_step(p, study.opt.run, definite, study.dir + "/iterations_definite.dat");
  treatments_table(study.opt, study.newton, sym, def, study.dir, study.command);
  return definite_failure_transcript(p, study.opt.run, definite, study.dir, study.program);
}

}  // namespace ch04
