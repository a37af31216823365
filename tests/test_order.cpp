// Observed orders of accuracy on a problem with a closed-form solution: the damped single spring of Chapter 2
// (src/model/single_spring.hpp), m s'' + D s' + K s = 0, exactly linear inside the cloth model.
#include "integrators/method_registry.hpp"
#include "model/single_spring.hpp"
#include "oscillator.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace cloth;

namespace {

constexpr double K = cloth_test::Oscillator::K, D = cloth_test::Oscillator::D, m = cloth_test::Oscillator::m,
                 s0 = cloth_test::Oscillator::s0;

// The error at T of `method` with step h against the closed form (oscillator.hpp).
double error_at_T(const std::string& method, double h) {
  NewtonSettings newton;
  newton.tolerance = 1e-13;  // Newton's error must be far below the method's
  return cloth_test::oscillator_error([&](ForceField& field) { return make_stepper(method, field, {newton}); }, h);
}

// Least-squares slope of log(error) against log(h) over h, h/2, h/4.
double fitted_order(const std::string& method, double h) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k < 3; ++k) {
    const double lh = std::log(h / (1 << k));
    const double le = std::log(error_at_T(method, h / (1 << k)));
    sx += lh, sy += le, sxx += lh * lh, sxy += lh * le;
  }
  return (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
}

}  // namespace

TEST_CASE("the closed form solves the oscillator: the model's force on the displaced spring is -K s") {
  const Scene scene(single_spring_params(K, D));
  ForceField field(scene);
  Vector x, v, f(scene.dof_count());
  single_spring_initial_state(scene, s0, x, v);
  v.setConstant(0);
  for (Eigen::Index i = 1; i < v.size(); i += 3) v[i] = 0.3;
  field.forces(x, v, f);
  for (Eigen::Index i = 0; i < f.size(); ++i)
    CHECK(f[i] == doctest::Approx(i % 3 == 1 ? -K * s0 - D * 0.3 : 0.0).epsilon(1e-12));
  // and the closed form satisfies its ODE: s'' by central differences equals -(K s + D s') / m
  const double t = 0.37, e = 1e-4;
  const auto a = single_spring_exact(K, D, m, s0, t);
  const double s_dd = (single_spring_exact(K, D, m, s0, t + e).ds - single_spring_exact(K, D, m, s0, t - e).ds) / (2 * e);
  CHECK(s_dd == doctest::Approx(-(K * a.s + D * a.ds) / m).epsilon(1e-6));
}

TEST_CASE("every registered method's observed order on the damped spring, from errors at h, h/2, h/4, is the order "
          "it claims within 0.15") {
  for (const Method& m : methods()) {
    if (m.family == MethodFamily::constrained) continue;  // holds the spring at its rest length: no oscillator left
    // h small enough to be in the asymptotic range, large enough to keep the errors above rounding.
    const double h = m.order == 1 ? 0.003125 : 0.0125;
    const double p = fitted_order(m.name, h);
    INFO(m.name << ": fitted order " << p << ", claimed " << m.order);
    CHECK(std::abs(p - m.order) < 0.15);
  }
}
