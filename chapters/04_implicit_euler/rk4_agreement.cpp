// Implicit Euler against RK4: its distance from an accurate solution, and what halving h does to it.
#include "report.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"

#include <stdexcept>

namespace ch04 {

using namespace cloth;

// Implicit Euler against RK4 on the damped report scene (K = 200, D = 20) to t = 1 s: RK4 at h = 1e-3 is the
// reference (its own error, estimated from RK4 at h/2, is far smaller), and implicit Euler's distance from it
// should halve with h, the method being of first order. Distances are max norms over all coordinates.
void agreement_with_rk4(const Study& study) {
  const SceneParams& report_scene = study.opt.scene;
  RunSettings run = study.opt.run;
  const NewtonSettings& newton = study.newton;
  const std::string& dir = study.dir;
  const std::string& command = study.command;
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

}  // namespace ch04
