// Chapter 8: embedded pairs and step-size control. Both rows of every pair have their orders (the generated
// conditions and the observed orders on the closed-form oscillator), the estimate is the lower row's true local
// error, control keeps the global error near the tolerance, FSAL saves one evaluation per step (counted), and a
// rejected step leaves the state as it was.
#include "base/input_error.hpp"
#include "integrators/adaptive_simulate.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/order_conditions.hpp"
#include "model/single_spring.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace cloth;

namespace {

constexpr double K = 50, D = 2, m = 1, s0 = -0.005;

// The largest deviation of a free particle's displacement (or velocity / omega) from the closed form at t.
double oscillator_error(const Scene& scene, const Vector& x, const Vector& v, double t) {
  const OscillatorState exact = single_spring_exact(K, D, m, s0, t);
  const Vector rest = scene.initial_positions();
  const double omega = std::sqrt(K / m);
  double error = 0;
  for (Eigen::Index i = 1; i < x.size(); i += 3)
    error = std::max({error, std::abs(x[i] - rest[i] - exact.s), std::abs(v[i] - exact.ds) / omega});
  return error;
}

// Error at T = 1 of fixed steps h with row b (embedded = false) or b-hat (the candidate minus the estimate).
double fixed_step_error(const ButcherTableau& t, double h, bool embedded) {
  const Scene scene(single_spring_params(K, D));
  ForceField field(scene);
  EmbeddedRungeKutta rk(field, t);
  Vector x, v;
  single_spring_initial_state(scene, s0, x, v);
  const auto steps = std::llround(1.0 / h);
  for (long long n = 0; n < steps; ++n) {
    rk.restart();
    rk.attempt(h, x, v);
    if (embedded) {
      x = rk.candidate_x() - rk.error_x();
      v = rk.candidate_v() - rk.error_v();
    } else {
      rk.accept(x, v);
    }
  }
  return oscillator_error(scene, x, v, 1.0);
}

// The damped oscillator of one spring (the closed form of single_spring_exact) at rest displacement s0, its force
// field and a run over T = 1 s: what the driver tests below start from.
struct Oscillator {
  const Scene scene{single_spring_params(K, D)};
  ForceField field{scene};
  RunSettings run;
  Vector x0, v0;
  Oscillator() {
    run.t_end = 1.0;
    single_spring_initial_state(scene, s0, x0, v0);
  }
};

}  // namespace

TEST_CASE("rooted trees: 1, 1, 2, 4, 9, 20, 48, 115 of orders 1 to 8, with Butcher's densities") {
  const int expected[] = {0, 1, 1, 2, 4, 9, 20, 48, 115};
  int counts[9] = {};
  for (const RootedTree& t : rooted_trees()) ++counts[t.order];
  for (int p = 1; p <= 8; ++p) CHECK(counts[p] == expected[p]);
  // The conditions of order 4 as Butcher's Table 312(I) writes them.
  std::vector<std::string> order4;
  for (const RootedTree& t : rooted_trees())
    if (t.order == 4) order4.push_back(t.condition);
  CHECK(order4 == std::vector<std::string>{"sum b_i c_i^3 = 1/4", "sum b_i c_i a_ij c_j = 1/8",
                                           "sum b_i a_ij c_j^2 = 1/12", "sum b_i a_ij a_jk c_k = 1/24"});
  // Sum over trees of order p of 1/(sigma gamma) ... is not needed; the densities of order 5 multiply out to the
  // known set {5, 10, 15, 20, 20, 30, 40, 60, 120}.
  std::vector<long long> densities;
  for (const RootedTree& t : rooted_trees())
    if (t.order == 5) densities.push_back(t.density);
  std::sort(densities.begin(), densities.end());
  CHECK(densities == std::vector<long long>{5, 10, 15, 20, 20, 30, 40, 60, 120});
}

TEST_CASE("every built-in pair satisfies the conditions of both rows exactly to its claimed orders, and no more") {
  for (const Method* row : methods_of(MethodFamily::embedded_runge_kutta)) {
    const ButcherTableau& t = *row->tableau;
    INFO(t.name);
    CHECK_NOTHROW(validate(t));
    for (int p = 1; p <= t.order; ++p) CHECK(order_condition_defect(t, p) < 1e-13);
    for (int p = 1; p <= t.embedded_order; ++p) CHECK(order_condition_defect(t, p, true) < 1e-13);
    CHECK(order_condition_defect(t, t.order + 1) > 1e-5);
    CHECK(order_condition_defect(t, t.embedded_order + 1, true) > 1e-5);
  }
  CHECK(embedded_tableau_from_argument("dopri5").first_same_as_last());
  CHECK(embedded_tableau_from_argument("tsit5").first_same_as_last());
  CHECK(embedded_tableau_from_argument("bs32").first_same_as_last());
  CHECK_FALSE(embedded_tableau_from_argument("rkf45").first_same_as_last());
  CHECK_FALSE(embedded_tableau_from_argument("cash_karp").first_same_as_last());
}

TEST_CASE("the paper's Dormand-Prince table in chapters/08_adaptive_step/dopri5.tableau is the built-in dopri5") {
  const ButcherTableau file = read_tableau(std::string(CLOTH_SOURCE_DIR) + "/chapters/08_adaptive_step/dopri5.tableau");
  const ButcherTableau builtin = embedded_tableau_from_argument("dopri5");
  CHECK(file.order == 5);
  CHECK(file.embedded_order == 4);
  CHECK((file.A - builtin.A).cwiseAbs().maxCoeff() == 0.0);
  CHECK((file.b_hat - builtin.b_hat).cwiseAbs().maxCoeff() == 0.0);
  // A wrong digit in b-hat is caught by the embedded row's conditions.
  CHECK_THROWS_WITH_AS(parse_tableau("order 2\nembedded_order 1\n0 0 0\n1 1 0\nb 1/2 1/2\nbhat 1 1\n", "t"),
                       doctest::Contains("for bhat but the order-1 condition sum bhat_i = 1"), InputError);
  CHECK_THROWS_WITH_AS(parse_tableau("order 2\n0 0 0\n1 1 0\nb 1/2 1/2\nbhat 1 0\n", "t"),
                       doctest::Contains("needs an 'embedded_order"), InputError);
  // An adaptive run needs the embedded row.
  CHECK_THROWS_WITH_AS(embedded_tableau_from_argument(std::string(CLOTH_SOURCE_DIR) +
                                                      "/chapters/03_runge_kutta/rk4_report.tableau"),
                       doctest::Contains("has no embedded row"), InputError);
}

TEST_CASE("observed orders of both rows of every pair on the closed-form oscillator") {
  for (const Method* row : methods_of(MethodFamily::embedded_runge_kutta)) {
    const ButcherTableau& t = *row->tableau;
    for (const bool embedded : {false, true}) {
      const int p = embedded ? t.embedded_order : t.order;
      INFO(t.name << (embedded ? " b-hat" : " b") << ", order " << p);
      // Steps small enough for the asymptotic regime, large enough to stay above rounding.
      const double h = p >= 5 ? 1.0 / 40 : p >= 3 ? 1.0 / 80 : 1.0 / 640;
      const double observed = std::log2(fixed_step_error(t, h, embedded) / fixed_step_error(t, h / 2, embedded));
      CHECK(observed == doctest::Approx(p).epsilon(0.15 / p));
    }
  }
}

TEST_CASE("the estimate is the true local error of the lower-order row") {
  const Scene scene(single_spring_params(K, D));
  ForceField field(scene);
  for (const Method* row : methods_of(MethodFamily::embedded_runge_kutta)) {
    const ButcherTableau& t = *row->tableau;
    INFO(t.name);
    EmbeddedRungeKutta rk(field, t);
    Vector x, v;
    single_spring_initial_state(scene, s0, x, v);
    const double h = t.order >= 4 ? 0.01 : 0.002;
    rk.attempt(h, x, v);
    // True errors of both rows after one step from the exact initial state.
    const double e_b = oscillator_error(scene, rk.candidate_x(), rk.candidate_v(), h);
    const Vector x_hat = rk.candidate_x() - rk.error_x(), v_hat = rk.candidate_v() - rk.error_v();
    const double e_hat = oscillator_error(scene, x_hat, v_hat, h);
    const double lower = t.order < t.embedded_order ? e_b : e_hat;
    double estimate = 0;
    const double omega = std::sqrt(K / m);
    for (Eigen::Index i = 1; i < x.size(); i += 3)
      estimate = std::max({estimate, std::abs(rk.error_x()[i]), std::abs(rk.error_v()[i]) / omega});
    CHECK(estimate == doctest::Approx(lower).epsilon(0.1));
    CHECK(std::min(e_b, e_hat) < 0.2 * lower);  // and the other row is much more accurate
  }
}

TEST_CASE_FIXTURE(Oscillator,
                  "error control keeps the global error of the oscillator within a modest factor of the tolerance") {
  for (const char* name : {"bs32", "rkf45", "dopri5", "tsit5", "cash_karp"}) {
    for (const ControllerKind controller : {ControllerKind::elementary, ControllerKind::pi}) {
      for (const double tol : {1e-6, 1e-8, 1e-10}) {
        INFO(std::string(name) << " " << std::string(controller_name(controller)) << " tol " << tol);
        EmbeddedRungeKutta rk(field, embedded_tableau_from_argument(name));
        AdaptiveSettings settings;
        settings.tolerances = {tol, tol};
        settings.controller = controller;
        const AdaptiveResult r = adaptive_simulate(rk, x0, v0, run, settings, false);
        REQUIRE(r.status == RunStatus::ok);
        CHECK(r.t == 1.0);
        const double error = oscillator_error(scene, r.x, r.v, 1.0);
        // Tolerance per step, not per run: the error accepted in each of the ~100 to 1000 steps adds up. Pairs
        // that advance with the higher row (local extrapolation) stay below tol here; rkf45 and bs32, which
        // advance with the row whose error they estimate (rkf45) or sit close to it, come within 16 times it.
        CHECK(error < 20 * tol);
        CHECK(error > 1e-3 * tol);  // and not wastefully below it
      }
    }
  }
}

TEST_CASE_FIXTURE(Oscillator,
                  "first same as last saves one evaluation per step, counted; rejected attempts keep their first stage") {
  for (const char* name : {"dopri5", "cash_karp", "rkf45", "bs32"}) {
    INFO(name);
    const ButcherTableau t = embedded_tableau_from_argument(name);
    EmbeddedRungeKutta rk(field, t);
    AdaptiveSettings settings;
    settings.tolerances = {1e-8, 1e-8};
    settings.first_step = 0.05;  // too large: the first attempts are rejected
    const AdaptiveResult r = adaptive_simulate(rk, x0, v0, run, settings, false);
    REQUIRE(r.status == RunStatus::ok);
    CHECK(r.rejected > 0);
    const long long attempts = r.accepted + r.rejected, s = t.stages();
    // Every attempt evaluates stages 2..s; the first stage is evaluated once at the start and, unless the pair is
    // FSAL, once after every accepted step but the last.
    const long long expected = 1 + (s - 1) * attempts + (t.first_same_as_last() ? 0 : r.accepted - 1);
    CHECK(r.counters.rhs_evaluations == expected);
  }
}

TEST_CASE_FIXTURE(Oscillator,
                  "a rejected step leaves the state untouched, bit for bit, and the next attempt starts from it") {
  run.t_end = 0.5;
  EmbeddedRungeKutta rk(field, embedded_tableau_from_argument("dopri5"));
  // Directly: an attempt far too large, then the state compared.
  Vector x = x0, v = v0;
  rk.attempt(0.5, x, v);
  CHECK(x == x0);
  CHECK(v == v0);
  // In the driver: after every rejection the next attempt starts at the same t from the same state.
  AdaptiveSettings settings;
  settings.tolerances = {1e-9, 1e-9};
  settings.first_step = 0.2;
  StepAttempt previous{};
  Vector px, pv;
  long long checked = 0;
  const AdaptiveResult r = adaptive_simulate(rk, x0, v0, run, settings, false,
                                             [&](const StepAttempt& a, const Vector& ax, const Vector& av) {
                                               if (checked >= 0 && px.size() > 0 && !previous.accepted) {
                                                 CHECK(a.t == previous.t);
                                                 CHECK(a.h < previous.h);
                                                 CHECK(ax == px);
                                                 CHECK(av == pv);
                                                 ++checked;
                                               }
                                               previous = a;
                                               px = ax;
                                               pv = av;
                                             });
  CHECK(r.rejected > 0);
  CHECK(checked == r.rejected);
}

TEST_CASE_FIXTURE(Oscillator,
                  "below the floor on h the run stops as step_size_too_small, with the state it reached") {
  EmbeddedRungeKutta rk(field, embedded_tableau_from_argument("dopri5"));
  AdaptiveSettings settings;
  settings.tolerances = {1e-12, 1e-12};
  settings.min_step = 0.01;  // the oscillator needs smaller steps than this at tolerance 1e-12
  const AdaptiveResult r = adaptive_simulate(rk, x0, v0, run, settings, true);
  CHECK(r.status == RunStatus::step_failed);
  CHECK(r.failure == StepFailureKind::step_size_too_small);
  CHECK(r.message.find("step size too small") != std::string::npos);
  CHECK(r.t < 1.0);
  CHECK(r.x.allFinite());
}

TEST_CASE_FIXTURE(Oscillator,
                  "frames fall on their exact times by Hermite interpolation, and the last one is the final state") {
  run.frames = 7;  // times that no step is aimed at
  EmbeddedRungeKutta rk(field, embedded_tableau_from_argument("dopri5"));
  AdaptiveSettings settings;
  settings.tolerances = {1e-10, 1e-10};
  const AdaptiveResult r = adaptive_simulate(rk, x0, v0, run, settings, true);
  REQUIRE(r.frames.size() == 8);
  Vector all(3 * scene.particle_count());
  scene.all_positions(r.x, all);
  CHECK(r.frames.back().positions == all);
  const Vector rest_all = [&] {
    Vector a(3 * scene.particle_count());
    scene.all_positions(scene.initial_positions(), a);
    return a;
  }();
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    const double t = static_cast<double>(k) / 7;
    CHECK(r.frames[k].t == doctest::Approx(t).epsilon(1e-14));
    // Every free particle's displacement along y against the closed form, to the interpolant's O(h^4).
    const double s = single_spring_exact(K, D, m, s0, t).s;
    double worst = 0;
    for (int p = 0; p < scene.particle_count(); ++p)
      if (!scene.is_pinned(p)) worst = std::max(worst, std::abs(r.frames[k].positions[3 * p + 1] - rest_all[3 * p + 1] - s));
    CHECK(worst < 1e-7);
  }
}
