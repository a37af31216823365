// Chapter 4: implicit Euler on the report's cloth, each step solved by Newton's method on the analytic sparse
// Jacobian; Baraff and Witkin's one-iteration variant beside full Newton; the residuals of one stiff step; what the
// Newton matrix costs; the step as the minimisation of a potential. One run of the cloth by default; with
// --report-runs, the page's studies, in the order of the page, each in a file named for what it studies.
#include "potential_study.hpp"
#include "report.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"
#include "program/run_outputs.hpp"

#include <functional>
#include <string>

using namespace cloth;

namespace {

// --report-runs: the chapter's studies. `newton_for(K, D)` gives the full-Newton settings at (K, D), as main checked
// them before any run. Returns the exit status of an interrupted run, else 0 (a run that fails is a result).
int report_runs(const ch04::Study& study, const std::function<NewtonSettings(double, double)>& newton_for) {
  if (const int status = ch04::full_against_one(study, newton_for)) return status;  // report_runs.md
  ch04::stiff_step(study);                                                         // stiff_step.md
  throw_if_interrupted();
  if (const int status = ch04::newton_matrices(study)) return status;               // jacobian_treatments.md
  if (const int status = ch04::large_step_and_cg(study)) return status;             // stiff_large_step.md, cg_run.md
  ch04::agreement_with_rk4(study);                                                  // rk4_agreement.md
  ch04::flat_step_history(study.opt.scene, study.dir, study.command);              // flat_step.md
  ch04::curtain_runs(study.opt.scene, study.opt.run, study.dir, study.command);    // curtain_runs.md
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
  cli.declare_outputs([&](const Options&) { return want_report_runs ? ch04::report_outputs() : run_output_specs(); });
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
      prepare_declared_outputs(opt.run.out_dir, run_output_specs(), ch04::report_outputs());
      return ch04::run_cloth(opt.scene, opt.run, settings, opt.run.out_dir, cli.program()).status;
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
    prepare_declared_outputs(opt.run.out_dir, ch04::report_outputs(), run_output_specs());
    return report_runs({opt, newton, opt.run.out_dir, cli.program(), reader_command(argc, argv)}, newton_for);
  });
}
