// The stiff cloth at a large step, which the line search makes possible, and conjugate gradients on the report
// scene: two numbers the page quotes in its prose.
#include "report.hpp"

#include "base/format_number.hpp"
#include "program/fragment.hpp"

namespace ch04 {

using namespace cloth;

namespace {

// One of the page's measured runs: the report scene at (K, D), full Newton on `solver` with the Jacobian
// `treatment`, into the subfolder `folder` of `--out`.
struct MeasuredRun {
  double K, D;
  RunSettings run;
  LinearSolverKind solver;
  StiffnessTreatment treatment;
  const char* folder;
};

Outcome measured(const Study& study, const MeasuredRun& m) {
  return run_cloth(with_K_and_D(study.opt.scene, m.K, m.D), m.run, full_newton(study.newton, m.solver, m.treatment),
                   study.dir + "/" + m.folder, study.program);
}

}  // namespace

// Numbers the page quotes in its prose, each in a sentence of its own (Doxygen includes a file as a separate
// word, so the page includes each at the end of a line): the stiff cloth at a large step, which the line search
// makes possible, and conjugate gradients on the report scene.
int large_step_and_cg(const Study& study) {
  const std::string& dir = study.dir;
  RunSettings large_step = study.opt.run;
  large_step.dt = 0.1;
  const Outcome a = measured(study, {.K = 1e5, .D = 0, .run = large_step, .solver = LinearSolverKind::automatic,
                                     .treatment = StiffnessTreatment::exact, .folder = measured_run_folders[1]});
  if (a.status >= 128) return a.status;
  write_text_fragment(dir + "/stiff_large_step.md",
                      "At h = " + format_number(large_step.dt) + " s it takes " + std::to_string(a.result.steps) +
                          " steps to t = " + format_number(a.result.t) + " s, with " +
                          format_number(a.result.newton_iterations_per_step(), 2) + " Newton iterations per step.");
  RunSettings short_run = study.opt.run;
  short_run.t_end = 0.3;
  const Outcome b = measured(study, {.K = 50, .D = 0, .run = short_run, .solver = LinearSolverKind::cg,
                                     .treatment = StiffnessTreatment::definite, .folder = measured_run_folders[2]});
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

}  // namespace ch04
