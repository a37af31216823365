// Every method converges to the same motion of the report's cloth as h shrinks, at the rate its order predicts;
// and explicit Euler, the one-stage tableau run by the Runge-Kutta engine, is Chapter 2's two lines bit for bit.
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace cloth;

namespace {

Vector final_positions(const std::string& method, double h, double t_end) {
  const Scene scene{SceneParams{}};  // the report scene, K = 50, D = 0
  ForceField field(scene);
  NewtonSettings newton;
  newton.tolerance = 1e-12;
  auto stepper = make_stepper(method, field, {newton});
  RunSettings run;
  run.dt = h;
  run.t_end = t_end;
  const RunResult r = simulate(*stepper, run, false);
  REQUIRE(r.status == RunStatus::ok);
  return r.x;
}

// Explicit Euler as Chapter 2 writes it: x1 = x0 + h v0, v1 = v0 + h a(x0, v0).
class TwoLineEuler final : public Stepper {
 public:
  explicit TwoLineEuler(ForceField& field) : Stepper(field), a_(field.dof_count()) {}
  [[nodiscard]] std::string name() const override { return "two_line_euler"; }
  bool step(double h, Vector& x, Vector& v) override {
    field_.acceleration(x, v, a_);
    x += h * v;
    v += h * a_;
    ++counters_.steps;
    return true;
  }

 private:
  Vector a_;
};

}  // namespace

TEST_CASE("explicit Euler, the one-stage tableau run by the engine, gives the two-line step's final state bit for bit") {
  for (const double damping : {0.0, 2.0}) {  // both finish the 100 steps at K = 50
    SceneParams p;
    p.damping = damping;
    const Scene scene{p};
    ForceField field(scene);
    TwoLineEuler two_lines(field);
    const auto registered = make_stepper("explicit_euler", field);
    RunSettings run;
    run.t_end = 1;
    const RunResult a = simulate(two_lines, run, false);
    const RunResult b = simulate(*registered, run, false);
    CHECK(a.steps == 100);
    CHECK((a.x.array() == b.x.array()).all());  // exact equality, not approximate
    CHECK((a.v.array() == b.v.array()).all());
    CHECK(b.counters.rhs_evaluations == 100);
  }
}

TEST_CASE("every method approaches RK4 at h = 1e-4 on the report scene as its order predicts") {
  const double T = 0.2;
  const Vector reference = final_positions("rk4", 1e-4, T);  // error ~ 1e-14 m, far below every other
  struct Case {
    const char* method;
    double h;
    double order;
  };
  const Case cases[] = {{"explicit_euler", 2e-3, 1}, {"symplectic_euler", 2e-3, 1}, {"heun", 4e-3, 2},
                        {"midpoint", 4e-3, 2},       {"kutta3", 4e-3, 3},           {"rk4", 2e-3, 4},
                        {"rule38", 2e-3, 4},         {"implicit_euler", 4e-3, 1}};
  for (const Case& c : cases) {
    const double e1 = (final_positions(c.method, c.h, T) - reference).lpNorm<Eigen::Infinity>();
    const double e2 = (final_positions(c.method, c.h / 2, T) - reference).lpNorm<Eigen::Infinity>();
    const double observed = std::log2(e1 / e2);
    INFO(std::string(c.method) << ": error " << e1 << " m at h = " << c.h << ", " << e2 << " m at h/2, observed order " << observed);
    CHECK(std::abs(observed - c.order) < 0.3);  // halving h divides the error by 2^p
    CHECK(e2 < 0.05);                            // and they are close to the same motion
  }
}
