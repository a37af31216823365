// Local/global time stepping (Liu et al. 2013) converges to Newton's implicit Euler step as its iterations grow,
// damped or not and with pinned particles, and its first iterations lower implicit Euler's objective.
#include <doctest/doctest.h>

#include "integrators/implicit_euler.hpp"
#include "integrators/local_global.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/symplectic_euler.hpp"
#include "base/input_error.hpp"
#include "light_cloth.hpp"

#include <cmath>

using namespace cloth;
using cloth::testing::light_cloth;
using cloth::testing::moving_state;
using cloth::testing::State;

TEST_CASE("local/global converges to the Newton implicit Euler step as its iterations grow") {
  // At h = 1e-3 (h^2 K / m = 1.6) the iteration contracts fast and reaches Newton's step to rounding; at a frame
  // step h = 1/60 (h^2 K / m = 444) it still converges, but slowly: the global matrix gives every spring its full
  // stiffness in every direction, while the true one has almost none across the spring (Chapter 10).
  struct Case {
    double h;
    int most_iterations;
    double final_error;  // what the last count must reach
  };
  for (const Case c : {Case{1e-3, 1024, 1e-12}, Case{1.0 / 60, 16384, 1e-5}}) {
    for (double D : {0.0, 0.01}) {
      CAPTURE(D);
      CAPTURE(c.h);
      const Scene scene(light_cloth(D));
      const State s = moving_state(scene);
      ForceField newton_field(scene);
      NewtonSettings tight;
      tight.tolerance = 1e-10;  // |dv| below about 1e-10 m/s: x1 to ~1e-12 m
      // Local/global's damper acts along the current direction, as in the stage equation the residual search
      // solves (the potential search freezes it for the step, an O(h^2) change).
      tight.line_search = LineSearch::residual;
      ImplicitEuler newton(newton_field, tight);
      Vector xn = s.x, vn = s.v;
      const bool converged = newton.step(c.h, xn, vn);
      INFO(newton.failure().reason);
      REQUIRE(converged);
      REQUIRE((xn - s.x).cwiseAbs().maxCoeff() > 1e-4);  // the step moves the cloth

      double previous = INFINITY, first = 0;
      for (int iterations = 1; iterations <= c.most_iterations; iterations *= 4) {
        CAPTURE(iterations);
        ForceField field(scene);
        LocalGlobal lg(field, iterations);
        Vector x = s.x, v = s.v;
        REQUIRE(lg.step(c.h, x, v));
        const double error = (x - xn).cwiseAbs().maxCoeff();
        if (iterations == 1) first = error;
        // Every four-fold increase brings it closer, until it reaches Newton's step to rounding.
        CHECK((error < previous || error < 1e-14));
        CHECK((v - (x - s.x) / c.h).cwiseAbs().maxCoeff() <= 1e-9 * (1 + v.cwiseAbs().maxCoeff()));
        CHECK(lg.counters().factorizations == 1);
        CHECK(lg.counters().linear_solves == iterations);
        previous = error;
      }
      CHECK(first > 1e-5);  // one iteration is not yet implicit Euler
      CHECK(previous <= c.final_error);
    }
  }
}

TEST_CASE("local/global factors once per step size and refuses fewer than one iteration") {
  const Scene scene(light_cloth(0.0));
  ForceField field(scene);
  LocalGlobal lg(field, 3);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  for (int k = 0; k < 5; ++k) REQUIRE(lg.step(0.01, x, v));
  REQUIRE(lg.step(0.005, x, v));
  CHECK(lg.counters().factorizations == 2);
  CHECK(lg.counters().steps == 6);
  CHECK(lg.name() == "local_global");
  CHECK_THROWS_AS(LocalGlobal(field, 0), InputError);
}

TEST_CASE("the registry makes local/global with the iterations its settings ask for") {
  const Scene scene(light_cloth(0.01));
  ForceField field(scene);
  MethodSettings settings;
  settings.local_global_iterations = 7;
  const auto stepper = make_stepper("local_global", field, settings);
  REQUIRE(stepper->name() == "local_global");
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  REQUIRE(stepper->step(0.01, x, v));
  CHECK(stepper->counters().linear_solves == 7);
  CHECK(find_method("local_global").order == 1);
}
