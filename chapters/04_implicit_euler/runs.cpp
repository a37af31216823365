// One run of the cloth with given Newton settings, the runs' folders and the files --report-runs declares.
#include "report.hpp"

#include "integrators/method_registry.hpp"
#include "program/output_kinds.hpp"
#include "program/progress.hpp"
#include "program/run_outputs.hpp"

#include <cstdio>
#include <utility>

namespace ch04 {

using namespace cloth;

Outcome run_cloth(const SceneParams& params, RunSettings run, const NewtonSettings& newton, const std::string& dir,
                  const std::string& program) {
  const Scene scene(params);
  ForceField field(scene);
  const auto made = make_newton_stepper("implicit_euler", field, {newton});  // resolves the automatic solver choice
  NewtonStepper& stepper = *made;
  run.out_dir = dir;
  run.progress = terminal_progress(program);
  RunResult result = simulate(stepper, run);
  const int status = finish_run(result, stepper, run, program, newton_run_lines(stepper.settings()));
  if (result.steps > 0)
    std::printf("  Newton iterations per step: %.3f (%lld in %lld steps), %lld factorizations\n",
                result.newton_iterations_per_step(),
                result.counters.newton_iterations, result.steps, result.counters.factorizations);
  return {status, std::move(result), stepper.name()};
}

NewtonSettings full_newton(NewtonSettings newton, LinearSolverKind solver, StiffnessTreatment treatment) {
  newton.solver = solver;
  newton.treatment = treatment;
  newton.variant = NewtonVariant::full;
  return newton;
}

std::string report_folder(const char* variant, const ReportCase& c) { return std::string(variant) + "_" + c.name(); }

OutputList report_outputs() {
  using namespace cloth::output_kinds;
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

}  // namespace ch04
