// Implicit Euler damps a rigid rotation (Chapter 10, "Why implicit Euler damps a rotation"): two particles turning
// about a pinned edge on stiff springs, stepped by implicit Euler at frame steps, against the stiff-limit recurrence
// the page derives; the exact motion, followed by RK4 at a small step, keeps turning.
#include <doctest/doctest.h>

#include "integrators/method_registry.hpp"
#include "model/single_spring.hpp"

#include <cmath>

using namespace cloth;

namespace {

// The rate of turning about the pinned edge's line (y = d, z = 0) of the first free particle: (r x v)_x / |r|^2,
// positive when the far edge rises.
double turning_rate(const Scene& scene, const Vector& x, const Vector& v) {
  const double dy = x[1] - (scene.grid().N - 1) * scene.grid().d, dz = x[2];
  return -(dy * v[2] - dz * v[1]) / (dy * dy + dz * dz);
}

// The page's recurrence: step k turns the spring by a_k, a_1 = atan(h w0), a_{k+1} = atan(sin a_k / (2 - cos a_k)),
// and leaves it turning at sin(a_k) / h.
double predicted_rate(double h, double w0, int steps) {
  double a = std::atan(h * w0);
  for (int k = 1; k < steps; ++k) a = std::atan(std::sin(a) / (2 - std::cos(a)));
  return std::sin(a) / h;
}

double rate_after(const std::string& method, NewtonVariant variant, double h, int steps, double K, double w0) {
  SceneParams p = single_spring_params(K, 0);
  p.initial_swing = w0;
  const Scene scene(p);
  ForceField field(scene);
  MethodSettings settings;
  settings.newton.variant = variant;
  settings.newton.max_iterations = 100;  // full Newton from a fast turn needs more than the default 20 (Chapter 10)
  settings.newton.tolerance = 1e-6;
  auto stepper = make_stepper(method, field, settings);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  REQUIRE(turning_rate(scene, x, v) == doctest::Approx(w0).epsilon(1e-14));
  for (int k = 0; k < steps; ++k) REQUIRE(stepper->step(h, x, v));
  return turning_rate(scene, x, v);
}

}  // namespace

TEST_CASE("implicit Euler slows a stiff rigid rotation as the stiff-limit recurrence says; RK4 keeps it") {
  const double K = 1e6, w0 = 10;  // h sqrt(K/m) >= 16 at these steps: the stiff limit
  for (const double h : {1.0 / 30, 1.0 / 60}) {
    CAPTURE(h);
    const int steps = static_cast<int>(std::lround(1 / h));  // one second
    const double predicted = predicted_rate(h, w0, steps);
    CHECK(predicted < 0.5 * w0);  // the damping is large: a test that cannot miss it
    for (const NewtonVariant variant : {NewtonVariant::full, NewtonVariant::one}) {
      const double measured = rate_after("implicit_euler", variant, h, steps, K, w0);
      CHECK(measured == doctest::Approx(predicted).epsilon(2e-3));
    }
    // The small-angle form of the page, w0 / sqrt(1 + 2 h w0^2 t), to a few per cent.
    CHECK(predicted == doctest::Approx(w0 / std::sqrt(1 + 2 * h * w0 * w0)).epsilon(0.03));
  }
  CHECK(rate_after("rk4", NewtonVariant::full, 1e-4, 10000, K, w0) == doctest::Approx(w0).epsilon(1e-3));
}
