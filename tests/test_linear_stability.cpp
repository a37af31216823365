// Linear stability on the undamped oscillator (stability functions R(z) at z = i h omega), explicit Euler's
// energy growth, and implicit Euler's unconditional stability on the stiff report scene.
#include "model/single_spring.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>

using namespace cloth;

namespace {

// Energy after n steps over the initial energy, for the undamped spring with omega = 10 rad/s.
// The oscillator is w' = -i omega w with w = omega s + i s', E = m |w|^2 / 2, so one step of a Runge-Kutta
// method multiplies E by exactly |R(-i h omega)|^2.
double energy_ratio(const std::string& method, double h_omega, int n, double s0) {
  const double K = 100, omega = 10;
  const Scene scene(single_spring_params(K, 0));
  ForceField field(scene);
  auto stepper = make_stepper(method, field);
  Vector x, v;
  single_spring_initial_state(scene, s0, x, v);
  const double E0 = field.energy(x, v).total();
  for (int k = 0; k < n; ++k) stepper->step(h_omega / omega, x, v);
  return field.energy(x, v).total() / E0;
}

double rk4_amplification_squared(double y) {
  const std::complex<double> z(0, -y);
  return std::norm(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
}

}  // namespace

TEST_CASE("RK4 is bounded at h omega = 2.7 and grows at h omega = 2.9 (its boundary is 2 sqrt 2)") {
  const int n = 30;
  // The growing run starts small so that it stays linear (|s| < d) while it grows; the bounded one starts large
  // so that it stays far above rounding while it decays.
  const double bounded = energy_ratio("rk4", 2.7, n, -0.01);
  const double growing = energy_ratio("rk4", 2.9, n, -1e-5);
  CHECK(bounded < 1e-3);   // |R|^2 = 0.52 per step
  CHECK(growing > 1e3);    // |R|^2 = 1.42 per step
  CHECK(bounded == doctest::Approx(std::pow(rk4_amplification_squared(2.7), n)).epsilon(1e-8));
  CHECK(growing == doctest::Approx(std::pow(rk4_amplification_squared(2.9), n)).epsilon(1e-8));
}

TEST_CASE("explicit Euler multiplies the undamped spring's energy by 1 + (h omega)^2 every step") {
  for (const double h_omega : {0.01, 0.1, 0.5}) {
    const double K = 100, omega = 10;
    const Scene scene(single_spring_params(K, 0));
    ForceField field(scene);
    auto euler = make_stepper("explicit_euler", field);
    Vector x, v;
    single_spring_initial_state(scene, -1e-4, x, v);
    double E = field.energy(x, v).total();
    for (int k = 0; k < 20; ++k) {
      euler->step(h_omega / omega, x, v);
      const double E1 = field.energy(x, v).total();
      CHECK(E1 / E == doctest::Approx(1 + h_omega * h_omega).epsilon(1e-10));
      E = E1;
    }
  }
}

TEST_CASE("implicit Euler stays bounded and loses energy every step on the report scene at K = 1e5, D = 0") {
  SceneParams p;  // the report scene
  p.stiffness = 1e5;
  p.damping = 0;
  const Scene scene(p);
  ForceField field(scene);
  auto stepper = make_stepper("implicit_euler", field);
  RunSettings run;
  run.dt = 0.01;  // h omega_max ~ 10: every explicit method of the book explodes here
  run.t_end = 0.5;
  const RunResult r = simulate(*stepper, run);
  REQUIRE(r.status == RunStatus::ok);
  for (std::size_t k = 1; k < r.energy.size(); ++k) {
    INFO("step " << k);
    CHECK(r.energy[k].energy.total() <= r.energy[k - 1].energy.total() * (1 + 1e-12));
  }
  CHECK(r.energy.back().energy.total() < 0.9 * r.energy.front().energy.total());
  CHECK(r.x.lpNorm<Eigen::Infinity>() < 10.0);  // nothing flew off: the cloth moved less than 10 m in 0.5 s
}
