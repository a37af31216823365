// The runs of Chapter 8's comparison with Boost.Odeint (comparison.hpp): the long-double reference, the
// registry's pairs, and odeint's controlled steppers. Each run is timed whole by program/timing.hpp.
#include "comparison.hpp"
#include "plain_cloth.hpp"

#include "integrators/adaptive_simulate.hpp"
#include "integrators/method_registry.hpp"
#include "program/interrupt.hpp"

#include <boost/numeric/odeint.hpp>

namespace ch08 {

using namespace cloth;
namespace odeint = boost::numeric::odeint;
using State = std::vector<double>;

namespace {

// [reference]
// The reference: odeint's controlled Dormand-Prince on the plain right-hand side in long double at tolerance
// `tol`; its credential is its distance from the same computation with Cash-Karp, a different pair.
template <class Stepper>
LongState long_double_run(const Scene& scene, double T, double tol, long long& steps) {
  PlainCloth<long double> plain(scene);
  // odeint is C++: the exception of a stop request (SIGINT, SIGTERM) passes through it, within one evaluation.
  const auto rhs = [&plain](const LongState& s, LongState& d, long double t) {
    throw_if_interrupted();
    plain(s, d, static_cast<double>(t));
  };
  LongState y = PlainCloth<long double>::initial_state(scene);
  const auto tolerance = static_cast<long double>(tol);
  const long double t0 = 0, t1 = T, first_step = 1e-4L;
  steps = static_cast<long long>(
      odeint::integrate_adaptive(odeint::make_controlled<Stepper>(tolerance, tolerance), rhs, y, t0, t1, first_step));
  return y;
}
// [reference]

}  // namespace

Reference long_double_reference(const Scene& scene, double T, double tolerance) {
  using Dopri5 = odeint::runge_kutta_dopri5<LongState, long double, LongState, long double>;
  using CashKarp = odeint::runge_kutta_cash_karp54<LongState, long double, LongState, long double>;
  Reference r;
  r.tolerance = tolerance;
  r.y = long_double_run<Dopri5>(scene, T, tolerance, r.steps);
  const LongState check = long_double_run<CashKarp>(scene, T, tolerance, r.check_steps);
  r.agreement = position_error(check, r.y);
  return r;
}

bool in_fair_project_set(const Row& r) {
  return r.series == "project_max" && (r.method == "dopri5" || r.method == "cash_karp");
}

std::vector<Row> project_runs(const Scene& scene, const LongState& ref, const ComparisonPlan& plan) {
  std::vector<Row> rows;
  // [project_runs]
  // Besides every pair with each norm (PI controller): dopri5 with the elementary controller, and dopri5 refusing
  // steps across which a spring turns by more than 0.5 rad.
  const auto project_run = [&](const std::string& series, const ButcherTableau& tableau, double tol,
                               const AdaptiveSettings& settings) {
    ForceField field(scene);
    EmbeddedRungeKutta rk(field, tableau);
    AdaptiveResult result;
    const Timing t = time_runs([&] {
      result = adaptive_simulate(rk, plan.run, settings, /*record=*/false);
      throw_if_interrupted();  // after a run a signal cut short
    }, {.runs = plan.runs});
    if (result.status == RunStatus::ok)
      rows.push_back({series, tableau.name, tol, position_error(result.x, ref), t, result.counters.rhs_evaluations});
  };
  for (const Method* row : methods_of(MethodFamily::embedded_runge_kutta)) {
    if (row->tableau->name == "heun_euler") continue;  // order 2: far off the diagram at these errors
    for (const NormKind norm : {NormKind::rms, NormKind::max})
      for (const double tol : plan.tolerances) {
        AdaptiveSettings settings;
        settings.tolerances = {tol, tol, norm};
        project_run(std::string("project_") + norm_name(norm), *row->tableau, tol, settings);
      }
  }
  for (const double tol : plan.tolerances) {
    AdaptiveSettings settings;
    settings.tolerances = {tol, tol};
    settings.controller = ControllerKind::elementary;
    project_run("project_rms_elementary", embedded_tableau_from_argument("dopri5"), tol, settings);
    settings.controller = ControllerKind::pi;
    settings.max_spring_turn = 0.5;
    project_run("project_rms_turn", embedded_tableau_from_argument("dopri5"), tol, settings);
  }
  // [project_runs]
  return rows;
}

std::vector<Row> odeint_runs(const Scene& scene, const LongState& ref, const ComparisonPlan& plan) {
  std::vector<Row> rows;
  const double T = plan.run.t_end;
  // [odeint_runs]
  // Boost.Odeint as its documentation shows it: integrate_adaptive with a controlled stepper made by
  // make_controlled(atol, rtol), from a first step of 1e-4 s (odeint adapts it from there).
  const double t0 = 0, first_step = 1e-4;
  const auto odeint_run = [&](const std::string& method, const std::string& series, double tol, auto stepper,
                              auto&& rhs) {
    State y;
    long long calls = 0;
    const Timing t = time_runs([&] {
      y = PlainCloth<double>::initial_state(scene);
      calls = 0;
      odeint::integrate_adaptive(stepper, [&](const State& s, State& d, double time) {
                                   throw_if_interrupted();
                                   ++calls;
                                   rhs(s, d, time);
                                 },
                                 y, t0, T, first_step);
    }, {.runs = plan.runs});
    rows.push_back({series, method, tol, position_error(y, ref), t, calls});
  };
  PlainCloth<double> plain(scene);
  ForceField field(scene);
  const int n = scene.dof_count();
  // The project's forces behind odeint's interface: the flat state seen as (x, v) without a copy.
  const auto project_rhs = [&](const State& y, State& dydt, double) {
    Eigen::Map<const Eigen::VectorXd> x(y.data(), n), v(y.data() + n, n);
    Eigen::Map<Eigen::VectorXd>(dydt.data(), n) = v;
    field.acceleration(x, v, Eigen::Map<Eigen::VectorXd>(dydt.data() + n, n));
  };
  using Dopri5 = odeint::runge_kutta_dopri5<State>;
  using CashKarp = odeint::runge_kutta_cash_karp54<State>;
  for (const double tol : plan.tolerances) {
    odeint_run("dopri5", "odeint_plain", tol, odeint::make_controlled<Dopri5>(tol, tol), plain);
    odeint_run("cash_karp54", "odeint_plain", tol, odeint::make_controlled<CashKarp>(tol, tol), plain);
    odeint_run("dopri5", "odeint_project_forces", tol, odeint::make_controlled<Dopri5>(tol, tol), project_rhs);
    odeint_run("cash_karp54", "odeint_project_forces", tol, odeint::make_controlled<CashKarp>(tol, tol), project_rhs);
  }
  // [odeint_runs]
  return rows;
}

}  // namespace ch08
