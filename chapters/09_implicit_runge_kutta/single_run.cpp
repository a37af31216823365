// One SUNDIALS run of the command line's scene, reported in the model page's terms: final.dat, run.txt with the
// solver's settings and work, the status of how it ended, and a summary line.
#include "benchmark.hpp"

#include "base/format_number.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/run_outputs.hpp"

#include <cstdio>

using namespace cloth;

namespace ch09 {

int single_run(const Options& opt, const SundialsSettings& settings, bool compare, const std::string& program) {
  const Scene scene(opt.scene);
  ForceField field(scene);
  Vector x, v;
  const Outcome out = sundials_run(settings, field, x, v);
  std::string error = "not computed";
  if (compare && out.ok) {
    try {
      error = format_number((x - rk4_positions(field, opt.run.t_end, 1e-5)).lpNorm<Eigen::Infinity>(), 4);
    } catch (const Interrupted&) {
      error = "not computed: interrupted";  // the run itself finished; run.txt says interrupted all the same
    }
  }
  // The run in the model page's terms: the last good state, and how the run ended.
  RunResult result;
  result.steps = out.steps;
  result.t = out.t;
  if (out.end.status == RunStatus::interrupted) result.status = RunStatus::interrupted;
  else if (!out.ok) stop_run(result, out.end.status, out.end.failure, out.steps + 1, out.failed_t, out.end.reason);
  write_final(opt.run.out_dir + "/final.dat", scene, x, v);
  const bool fixed = settings.solver == "arkode-backward-euler";
  KeyValues kv = {{"method", settings.solver},
                  {"K", format_number(opt.scene.stiffness, 10)},
                  {"damping", format_number(opt.scene.damping, 10)},
                  {"t_end", format_number(opt.run.t_end, 10)},
                  {"dt", fixed ? format_number(opt.run.dt, 10) : "adaptive"},
                  {"rtol", format_number(settings.rtol, 10)},
                  {"atol", format_number(settings.atol, 10)},
                  {"linear_solver", "klu"},
                  {"jacobian", stiffness_treatments().name(settings.treatment)},
                  {"steps", std::to_string(out.steps)},
                  {"t_reached", format_number(out.t, 10)},
                  {"convergence_failures", std::to_string(out.convergence_failures)},
                  {"processor_seconds", format_number(out.seconds, 4)},
                  {"newton_iterations", std::to_string(out.newton_iterations)},
                  {"linear_solver_setups", std::to_string(out.setups)},
                  {"error_vs_rk4", error},
                  {"sundials_flag", out.end.flag}};
  append_status(kv, result, interrupt_signal());
  write_key_values(opt.run.out_dir + "/run.txt", kv);
  if (!out.ok) return report_stop(result, settings.solver, program);
  std::printf("%s: %s, %ld steps to t = %g s in %.3f s of processor time, %ld Newton iterations (%ld convergence "
              "failures), %ld setups, error %s m\n",
              program.c_str(), settings.solver.c_str(), out.steps, out.t, out.seconds, out.newton_iterations,
              out.convergence_failures, out.setups, error.c_str());
  return 0;
}

}  // namespace ch09
