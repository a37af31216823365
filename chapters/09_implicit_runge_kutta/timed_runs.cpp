// The timed runs of the comparisons, one of each kind: the book's methods at a fixed step or under step control,
// and SUNDIALS at a tolerance, each the best of a few repeats, with its error at T against RK4 and its work.
#include "benchmark.hpp"

#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"
#include "integrators/configuration.hpp"
#include "integrators/implicit_step_control.hpp"
#include "integrators/method_registry.hpp"
#include "program/interrupt.hpp"
#include "program/timing.hpp"

#include <algorithm>

using namespace cloth;

namespace ch09 {

Timed fixed_step_run(ForceField& field, const std::string& method, double h, double newton_tol,
                     NewtonVariant variant, const Timing& timing, Vector* x_out) {
  MethodSettings settings;
  settings.newton.variant = variant;
  settings.newton.tolerance = newton_tol;
  Timed t{method, "h = " + format_number(h) + ", " + newton_variant_name(variant) + " Newton, tol " +
                      format_number(newton_tol)};
  RunSettings run;
  run.dt = h;
  run.t_end = timing.T;
  run.stop = &interrupt_flag();
  for (int k = 0; k < timing.repeats; ++k) {
    const auto stepper = make_newton_stepper(method, field, settings);
    const double start = thread_cpu_seconds();
    const RunResult r = simulate(*stepper, run, false);
    // An interrupted study stops here: the tables are written only once every run is whole, so none lists a run
    // that did not finish.
    throw_if_interrupted();
    t.seconds = std::min(t.seconds, thread_cpu_seconds() - start);
    if (r.status != RunStatus::ok) return t;
    t.factorizations = r.counters.factorizations;
    t.jacobians = r.counters.jacobian_assemblies;
    t.newton_iterations = r.counters.newton_iterations;
    t.forces = r.counters.rhs_evaluations;
    t.error = (r.x - timing.reference).lpNorm<Eigen::Infinity>();
    if (x_out) *x_out = r.x;
  }
  return t;
}

// From a first step of 1 ms: modified Newton on the stage equations as they are, stopped at a tenth of tol on its
// error estimate (the chapter's defaults for a controlled run).
Timed controlled_run(ForceField& field, const std::string& method, double tol, const Timing& timing) {
  Configuration c;
  c.method = method;
  c.settings.newton.variant = NewtonVariant::modified;
  c.settings.newton.line_search = LineSearch::residual;
  c.settings.newton.tolerance = 0.1 * tol;
  c.settings.newton.estimate_test = true;
  Timed t{configuration_name(c), "tol = " + format_number(tol, 3)};
  RunSettings run;
  run.dt = 1e-3;
  run.t_end = timing.T;
  run.frames = 1;
  run.stop = &interrupt_flag();
  StepControl control;
  control.tolerance = tol;
  for (int k = 0; k < timing.repeats; ++k) {
    DiagonallyImplicitRungeKutta stepper(field, builtin_implicit_tableau(method), c.settings.newton);
    const double start = thread_cpu_seconds();
    const ControlledRun r = simulate_controlled(stepper, run, control);
    t.seconds = std::min(t.seconds, thread_cpu_seconds() - start);
    throw_if_interrupted();
    if (r.result.status != RunStatus::ok) return t;
    t.factorizations = r.result.counters.factorizations;
    t.jacobians = r.result.counters.jacobian_assemblies;
    t.newton_iterations = r.result.counters.newton_iterations;
    t.forces = r.result.counters.rhs_evaluations;
    t.error = largest_distance(r.result.x, timing.reference);
  }
  return t;
}

Timed sundials_timed_run(ForceField& field, SundialsSettings settings, double tol, const std::string& who,
                         const Timing& timing) {
  Timed t{who, "rtol = atol = " + format_number(tol, 3)};
  settings.T = timing.T;
  settings.rtol = settings.atol = tol;
  for (int k = 0; k < timing.repeats; ++k) {
    Vector x, v;
    const Outcome out = sundials_run(settings, field, x, v);
    throw_if_interrupted();
    t.seconds = std::min(t.seconds, out.seconds);
    if (!out.ok) return t;
    t.error = largest_distance(x, timing.reference);
    t.factorizations = out.setups;
    t.jacobians = out.jacobian_evaluations;
    t.newton_iterations = out.newton_iterations;
    t.forces = out.rhs_evaluations;
  }
  return t;
}

}  // namespace ch09
