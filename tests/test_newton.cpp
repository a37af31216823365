// Newton's method inside implicit Euler: quadratic convergence on a stiff step, the failure policy (a step is
// never accepted unconverged), Baraff and Witkin's one-iteration step, and which solver takes which matrix.
#include "base/input_error.hpp"
#include "integrators/implicit_euler.hpp"
#include "integrators/simulate.hpp"
#include "program/run_outputs.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace cloth;

namespace {

SceneParams stiff_scene() {
  SceneParams p;  // the report scene at K = 1e5: h omega_max ~ 10 at h = 0.01
  p.stiffness = 1e5;
  p.damping = 0;
  return p;
}

}  // namespace

TEST_CASE("Newton converges quadratically on the first step of the stiff report scene (exact Jacobian, LU)") {
  const Scene scene(stiff_scene());
  ForceField field(scene);
  NewtonSettings s;
  s.solver = LinearSolverKind::lu;
  s.treatment = StiffnessTreatment::exact;
  s.tolerance = 1e-13;
  ImplicitEuler stepper(field, s);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  REQUIRE(stepper.step(0.01, x, v));
  const std::vector<double>& r = stepper.residual_history();
  REQUIRE(r.size() >= 5);
  // Once the residual is below 10 (close), every iteration squares it: r_{k+1} <= C r_k^2. C bounds
  // |J^-1| |J'| / 2; the measured ratios are 0.03 to 0.08. A linearly convergent iteration has r_{k+1} / r_k^2
  // growing like 1 / r_k and breaks the bound within two iterations. Iterates at the rounding floor (below
  // 1e-10, where the residual is noise of f's evaluation) are left out.
  const double C = 0.2;
  int checked = 0;
  for (std::size_t k = 0; k + 1 < r.size(); ++k) {
    if (r[k] > 10 || r[k + 1] < 1e-10) continue;
    INFO("iteration " << k << ": r_k = " << r[k] << ", r_{k+1} = " << r[k + 1]);
    CHECK(r[k + 1] <= C * r[k] * r[k]);
    ++checked;
  }
  CHECK(checked >= 3);
  CHECK(r.back() < 1e-10);
}

TEST_CASE("a step Newton cannot finish is refused: state unchanged, reason given, the run stops with status 3") {
  const Scene scene(stiff_scene());
  ForceField field(scene);
  NewtonSettings s;
  s.max_iterations = 2;  // the stiff first step needs about 7
  ImplicitEuler stepper(field, s);
  const Vector x0 = scene.initial_positions(), v0 = scene.initial_velocities();
  Vector x = x0, v = v0;
  CHECK_FALSE(stepper.step(0.01, x, v));
  CHECK(x == x0);
  CHECK(v == v0);
  CHECK(stepper.failure().reason.find("did not converge in 2 iterations") != std::string::npos);
  CHECK(stepper.failure().reason.find("|r|_inf") != std::string::npos);

  RunSettings run;
  run.t_end = 0.05;
  const RunResult result = simulate(stepper, run);
  CHECK(result.status == RunStatus::step_failed);
  CHECK(result.steps == 0);
  CHECK(result.message.find("step 1, t = 0.01") != std::string::npos);
  CHECK(report(result, stepper, "test") == 3);
}

TEST_CASE("Baraff and Witkin's one-iteration step is accepted as it is, and full Newton then finishes it") {
  const Scene scene(stiff_scene());
  ForceField field(scene);
  NewtonSettings one;
  one.variant = NewtonVariant::one;
  ImplicitEuler linearly_implicit(field, one);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  REQUIRE(linearly_implicit.step(0.01, x, v));
  CHECK(linearly_implicit.counters().newton_iterations == 1);
  // its answer is one Newton iterate, not the implicit Euler step: full Newton moves it
  NewtonSettings full;
  ImplicitEuler newton(field, full);
  Vector x_full = scene.initial_positions(), v_full = scene.initial_velocities();
  REQUIRE(newton.step(0.01, x_full, v_full));
  CHECK((v - v_full).lpNorm<Eigen::Infinity>() > 1e-3);
}

TEST_CASE("each linear solver is refused a matrix it cannot take") {
  SceneParams damped;
  damped.damping = 5;
  const Scene with_damping(damped), without_damping{SceneParams{}};
  NewtonSettings s;
  s.solver = LinearSolverKind::cg;
  s.treatment = StiffnessTreatment::symmetric;
  CHECK_THROWS_AS(validate(s, without_damping), InputError);
  s.treatment = StiffnessTreatment::definite;
  CHECK_NOTHROW(validate(s, with_damping));
  s.solver = LinearSolverKind::ldlt;
  s.treatment = StiffnessTreatment::exact;
  CHECK_NOTHROW(validate(s, with_damping));  // minimising, the exact matrix is Phi's Hessian: symmetric
  s.line_search = LineSearch::residual;
  CHECK_THROWS_AS(validate(s, with_damping), InputError);
  CHECK_NOTHROW(validate(s, without_damping));  // undamped, the exact Jacobian is symmetric
  s.solver = LinearSolverKind::lu;
  CHECK_NOTHROW(validate(s, with_damping));
}
