// Chapter 9's implicit methods: the recorded states of Chapter 4's implicit Euler reproduced by the implicit_euler
// tableau, observed orders against the closed form, implicit midpoint's exact energy on a linear oscillator,
// modified against full Newton, BDF2, and the tableaus the engine refuses.
#include "analysis/stability_function.hpp"
#include "base/input_error.hpp"
#include "integrators/bdf2.hpp"
#include "integrators/diagonally_implicit_runge_kutta.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "model/single_spring.hpp"
#include "oscillator.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

using namespace cloth;

namespace {

ImplicitTableau tableau(const std::string& name) { return builtin_implicit_tableau(name); }

// The largest difference between a run's final free state and a final.dat recorded from Chapter 4.
double difference_from_recorded(const Scene& scene, const Vector& x, const Vector& v, const std::string& file) {
  std::ifstream in(std::string(CLOTH_SOURCE_DIR) + "/tests/data/ch04_implicit_euler/" + file);
  REQUIRE(in.good());
  std::string line;
  double worst = 0;
  int compared = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    int i = 0, j = 0;
    Eigen::Matrix<double, 6, 1> recorded;
    words >> i >> j >> recorded[0] >> recorded[1] >> recorded[2] >> recorded[3] >> recorded[4] >> recorded[5];
    REQUIRE(words);
    const int s = scene.slot(scene.grid().particle(i, j));
    if (s >= scene.free_count()) continue;
    for (int k = 0; k < 3; ++k) {
      worst = std::max(worst, std::abs(x[3 * s + k] - recorded[k]));
      worst = std::max(worst, std::abs(v[3 * s + k] - recorded[3 + k]));
    }
    ++compared;
  }
  CHECK(compared == scene.free_count());
  return worst;
}

// The error at t = 1 s on the damped single spring against its closed form: cloth_test::oscillator_error
// (oscillator.hpp), with Newton's tolerance far below the truncation error.
using cloth_test::oscillator_error;

NewtonSettings tight() {
  NewtonSettings s;
  s.tolerance = 1e-13;
  s.solver = LinearSolverKind::lu;
  return s;
}

}  // namespace

TEST_CASE("implicit_euler on the stage machinery reproduces Chapter 4's recorded implicit Euler") {
  struct Case {
    const char* file;
    double K, D;
    LinearSolverKind solver;
    StiffnessTreatment treatment;
    int max_iterations;
    double tolerance;
  };
  // With direct solves Newton converges quadratically far below its tolerance, so the states agree to rounding,
  // whatever its first guess. CG's solves are inexact (relative residual 1e-10), and the stage predictor starts
  // Newton elsewhere than Chapter 4 did: the iterations end at another point within Newton's tolerance,
  // 1e-8 (1 + |V|_inf) with |V| about 20 m/s. The recordings solve the stage equation as it is, with the
  // dampers' current directions: the residual line search's equation (the default potential search freezes
  // them for the step, an O(h^2) change of the motion that test_incremental_potential.cpp measures).
  const Case cases[] = {
      {"K200_D20_full_ldu.dat", 200, 20, LinearSolverKind::ldu, StiffnessTreatment::exact, 20, 1e-12},
      {"K200_D20_full_cg.dat", 200, 20, LinearSolverKind::cg, StiffnessTreatment::definite, 20, 2e-7},
      {"K200_D20_one_ldu.dat", 200, 20, LinearSolverKind::automatic, StiffnessTreatment::exact, 1, 1e-12},
      {"K50_D0_full_ldlt.dat", 50, 0, LinearSolverKind::automatic, StiffnessTreatment::exact, 20, 1e-12},
      {"K50_D0_one_ldlt.dat", 50, 0, LinearSolverKind::automatic, StiffnessTreatment::exact, 1, 1e-12},
  };
  for (const Case& c : cases) {
    SceneParams p;
    p.stiffness = c.K;
    p.damping = c.D;
    const Scene scene(p);
    ForceField field(scene);
    NewtonSettings s;
    s.solver = c.solver;
    s.treatment = c.treatment;
    s.max_iterations = c.max_iterations;
    s.line_search = LineSearch::residual;
    DiagonallyImplicitRungeKutta stepper(field, tableau("implicit_euler"), s);
    RunSettings run;
    run.dt = 0.01;
    run.t_end = 0.3;
    const RunResult result = simulate(stepper, run, false);
    REQUIRE(result.status == RunStatus::ok);
    INFO(std::string(c.file));
    CHECK(difference_from_recorded(scene, result.x, result.v, c.file) <= c.tolerance);
  }
}

TEST_CASE("observed orders on the damped oscillator: every registered implicit method has the order its row claims") {
  int checked = 0;
  for (const Method* m : newton_methods()) {
    MethodSettings settings;
    settings.newton = tight();
    const auto make = [&](ForceField& field) { return make_stepper(m->name, field, settings); };
    // h from 1/80 to 1/320 (h omega from 0.09 to 0.02): the asymptotic range, errors well above rounding.
    const double e1 = oscillator_error(make, 1.0 / 80), e2 = oscillator_error(make, 1.0 / 160),
                 e3 = oscillator_error(make, 1.0 / 320);
    INFO(m->name << ": errors " << e1 << ", " << e2 << ", " << e3);
    // Implicit Euler approaches its order from below (0.89, then 0.95); the others are within 0.03.
    CHECK(std::abs(std::log2(e1 / e2) - m->order) <= 0.15);
    CHECK(std::abs(std::log2(e2 / e3) - m->order) <= 0.08);
    ++checked;
  }
  // implicit Euler, implicit midpoint, trapezoid, SDIRK2, SDIRK3, TR-BDF2, the two ESDIRK pairs, BDF2
  CHECK(checked == 9);
}

TEST_CASE("implicit midpoint keeps the energy of the undamped linear oscillator to rounding; backward Euler drains it") {
  const double K = 50, s0 = -0.005;
  const Scene scene(single_spring_params(K, 0));
  ForceField field(scene);
  Vector x0, v0;
  single_spring_initial_state(scene, s0, x0, v0);
  const double E0 = field.energy(x0, v0).total();
  REQUIRE(E0 > 0);
  const auto energy_after = [&](const char* name, int steps) {
    DiagonallyImplicitRungeKutta stepper(field, tableau(name), tight());
    Vector x = x0, v = v0;
    double worst = 0;
    for (int n = 0; n < steps; ++n) {
      REQUIRE(stepper.step(0.01, x, v));
      worst = std::max(worst, std::abs(field.energy(x, v).total() - E0));
    }
    return std::pair{field.energy(x, v).total(), worst};
  };
  // 5000 steps of h = 0.01 (h omega = 0.07, 56 periods). The midpoint rule conserves every quadratic invariant
  // of a linear system exactly (Cooper 1987), so what remains is rounding and Newton's 1e-13 tolerance.
  const auto [E_midpoint, drift_midpoint] = energy_after("implicit_midpoint", 5000);
  INFO("E0 = " << E0 << ", midpoint's largest deviation " << drift_midpoint);
  CHECK(drift_midpoint <= 1e-12 * E0);
  // Backward Euler multiplies each mode's amplitude by |R(i h omega)| = 1 / sqrt(1 + (h omega)^2) per step.
  const auto [E_euler, drift_euler] = energy_after("implicit_euler", 5000);
  const double h_omega = 0.01 * std::sqrt(K);
  CHECK(E_euler / E0 == doctest::Approx(std::pow(1 + h_omega * h_omega, -5000)).epsilon(0.02));
}

TEST_CASE("modified Newton converges to full Newton's solution with fewer factorizations") {
  // A 12 x 12 cloth at the report's (200, 20): its Newton matrices behave like the 20 x 20 one's at a fifth of
  // the factorization cost, which matters under the sanitizers.
  SceneParams p;
  p.grid.M = p.grid.N = 12;
  p.stiffness = 200;
  p.damping = 20;
  const Scene scene(p);
  ForceField field(scene);
  NewtonSettings full;
  full.tolerance = 1e-11;
  NewtonSettings modified = full;
  modified.variant = NewtonVariant::modified;
  RunSettings run;
  run.dt = 0.01;
  run.t_end = 0.3;
  for (const char* name : {"sdirk2", "trbdf2", "implicit_euler"}) {
    DiagonallyImplicitRungeKutta a(field, tableau(name), full), b(field, tableau(name), modified);
    const RunResult ra = simulate(a, run, false), rb = simulate(b, run, false);
    REQUIRE(ra.status == RunStatus::ok);
    REQUIRE(rb.status == RunStatus::ok);
    INFO(std::string(name) << ": factorizations full " << ra.counters.factorizations << ", modified " << rb.counters.factorizations
                            << ", differences " << (ra.x - rb.x).lpNorm<Eigen::Infinity>() << " m, "
                            << (ra.v - rb.v).lpNorm<Eigen::Infinity>() << " m/s");
    // Both stop at the same residual test: their states differ by the tolerance's worth, not by the method.
    CHECK((ra.x - rb.x).lpNorm<Eigen::Infinity>() <= 1e-8);
    CHECK((ra.v - rb.v).lpNorm<Eigen::Infinity>() <= 1e-7);
    CHECK(rb.counters.factorizations * 3 <= ra.counters.factorizations);
  }
}

TEST_CASE("the registered implicit tableaus satisfy their order conditions, TR-BDF2's embedded weights theirs") {
  for (const Method* m : newton_methods()) {
    if (!m->tableau) continue;
    const ImplicitTableau& t = builtin_implicit_tableau(m->name);
    INFO(t.method.name);
    CHECK_NOTHROW(validate(t));
    CHECK(order_condition_defect(t.method, t.method.order) <= 1e-14);
    // and not the next order: each claims exactly its order
    if (t.method.order < 4) CHECK(order_condition_defect(t.method, t.method.order + 1) > 1e-3);
  }
  const ImplicitTableau trbdf2 = tableau("trbdf2");
  ButcherTableau embedded = trbdf2.method;
  embedded.b = trbdf2.method.b_hat;
  CHECK(order_condition_defect(embedded, 3) <= 1e-14);
  CHECK(trbdf2.stiffly_accurate());
  CHECK(trbdf2.explicit_first_stage());
  CHECK_FALSE(tableau("implicit_midpoint").stiffly_accurate());
}

TEST_CASE("a fully implicit tableau (two-stage Gauss) is refused with a message that says so") {
  ImplicitTableau gauss;
  const double r = std::sqrt(3.0) / 6;
  gauss.method.name = "gauss2";
  gauss.method.order = 4;
  gauss.method.A.resize(2, 2);
  gauss.method.A << 0.25, 0.25 - r, 0.25 + r, 0.25;
  gauss.method.b = Eigen::Vector2d(0.5, 0.5);
  gauss.method.c = gauss.method.A.rowwise().sum();
  try {
    validate(gauss);
    FAIL("the Gauss tableau was accepted");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("a_12") != std::string::npos);
    CHECK(what.find("fully implicit") != std::string::npos);
  }
  ImplicitTableau wrong = tableau("sdirk2");
  wrong.method.order = 3;
  CHECK_THROWS_AS(validate(wrong), InputError);
}

TEST_CASE("R(z) of the implicit tableaus matches the closed forms; R(infinity) and A-stability from the tableau") {
  const double g = 1 - std::sqrt(2.0) / 2;
  const Complex points[] = {{-0.5, 0}, {-3, 2}, {0.2, -1.5}, {-40, 7}, {0, 5}};
  for (const Complex z : points) {
    INFO("z = " << z.real() << " + " << z.imag() << " i");
    CHECK(std::abs(stability_function(tableau("implicit_euler").method, z) - 1.0 / (1.0 - z)) <= 1e-14);
    const Complex pade11 = (1.0 + z / 2.0) / (1.0 - z / 2.0);
    CHECK(std::abs(stability_function(tableau("implicit_midpoint").method, z) - pade11) <= 1e-13);
    CHECK(std::abs(stability_function(tableau("trapezoid").method, z) - pade11) <= 1e-13);
    // Two-stage SDIRK, stiffly accurate: R = (1 + (1 - 2 gamma) z) / (1 - gamma z)^2.
    const Complex sdirk2 = (1.0 + (1 - 2 * g) * z) / ((1.0 - g * z) * (1.0 - g * z));
    CHECK(std::abs(stability_function(tableau("sdirk2").method, z) - sdirk2) <= 1e-13);
  }
  // Order p means R(z) = e^z + O(z^(p+1)): at z = 1e-2 the difference is about z^(p+1) / (p+1)! or smaller.
  for (const Method* m : newton_methods()) {
    if (!m->tableau) continue;
    const ButcherTableau& t = *m->tableau;
    const int p = t.order;
    const double small = 1e-2;
    const double defect = std::abs(stability_function(t, small) - std::exp(small));
    INFO(t.name);
    CHECK(defect <= std::pow(small, p + 1));
    CHECK(defect >= 1e-3 * std::pow(small, p + 2));
    CHECK(a_stable(t));
  }
  // Extrapolated from |z| = 1e4 to 4e4: accurate to about 1e-11.
  CHECK(std::abs(stability_at_infinity(tableau("implicit_midpoint").method) + 1) <= 1e-10);
  CHECK(std::abs(stability_at_infinity(tableau("trapezoid").method) + 1) <= 1e-10);
  for (const char* name : {"implicit_euler", "sdirk2", "sdirk3", "trbdf2"}) {
    INFO(std::string(name));
    CHECK(std::abs(stability_at_infinity(tableau(name).method)) <= 1e-10);
  }
  // An explicit method is not A-stable, and R grows without bound.
  for (const Method* m : methods_of(MethodFamily::explicit_runge_kutta)) {
    REQUIRE(m->tableau);
    CHECK_FALSE(a_stable(*m->tableau));
    CHECK(std::isinf(stability_at_infinity(*m->tableau)));
  }
  // A DIRK with a diagonal below 1/4 on two stages: gamma = 0.2 loses A-stability (the SDIRK2 family is A-stable
  // for gamma >= 1/4).
  ImplicitTableau weak = tableau("sdirk2");
  weak.method.A << 0.2, 0, 0.8, 0.2;
  weak.method.b = Eigen::Vector2d(0.8, 0.2);
  CHECK_FALSE(a_stable(weak.method));
}

TEST_CASE("make_newton_stepper makes every implicit row by name and refuses any other name with the list") {
  const Scene scene{SceneParams{}};
  ForceField field(scene);
  for (const Method* m : newton_methods()) CHECK(make_newton_stepper(m->name, field)->name() == m->name);
  try {
    make_newton_stepper("rk4", field);
    FAIL("rk4 was made as an implicit method");
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const char* name : {"'rk4'", "implicit_euler", "sdirk3", "trbdf2", "bdf2"}) {
      INFO(name);
      CHECK(what.find(name) != std::string::npos);
    }
  }
}

TEST_CASE("a tableau file carries an embedded pair: bhat and embedded_order, checked by the order conditions") {
  // The trapezoidal rule (order 2) with explicit Euler's weights (1, 0) embedded (order 1).
  const std::string rows = "order 2\n0 0 0\n1 1/2 1/2\nb 1/2 1/2\n";
  const ImplicitTableau pair = parse_implicit_tableau(rows + "bhat 1 0\nembedded_order 1\n", "pair");
  REQUIRE(pair.has_embedded());
  CHECK(pair.method.embedded_order == 1);
  CHECK(pair.method.b_hat == Eigen::Vector2d(1, 0));
  CHECK(pair.method.b == Eigen::Vector2d(0.5, 0.5));
  const auto refusal = [&](const std::string& extra) {
    try {
      parse_implicit_tableau(rows + extra, "pair");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const auto refused_with = [&](const std::string& extra, const std::string& part) {
    const std::string what = refusal(extra);
    INFO(extra << " -> " << what);
    CHECK(what.find(part) != std::string::npos);
  };
  refused_with("bhat 1 0\nembedded_order 2\n", "order-2 condition fails");
  refused_with("bhat 1/2 1/2\nembedded_order 2\n", "bhat equals b");
  refused_with("bhat 1 0 0\nembedded_order 1\n", "bhat has 3 weights: expected 2");
  refused_with("bhat 1 0\n", "needs an 'embedded_order q' line");
  refused_with("embedded_order 1\n", "needs a 'bhat' row");
  refused_with("bhat 1 x\nembedded_order 1\n", "pair:5: 'x' is not a number");
  refused_with("bhat 1 0\nbhat 1 0\nembedded_order 1\n", "a second 'bhat' row");
  // (0, 1), the last stage alone, is of order 1 exactly: accepted.
  CHECK(refusal("bhat 0 1\nembedded_order 1\n").empty());
}
