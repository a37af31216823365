// The damped single spring of Chapter 2 (src/model/single_spring.hpp), m s'' + D s' + K s = 0 exactly inside the
// cloth model, as the test problem with a closed-form solution: the error of any stepper against it, from which
// the tests of Chapters 3, 4 and 9 observe orders of accuracy.
#pragma once

#include "model/single_spring.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace cloth_test {

/// The oscillator of the order tests: K = 50 N/m, D = 2 N s/m, m = 1 kg, released from s0 = -5 mm, error at T = 1 s.
struct Oscillator {
  static constexpr double K = 50, D = 2, m = 1, T = 1, s0 = -0.005;
};

/// The error at t = T of the stepper `make(field)` returns, run with step h: the largest deviation of a free
/// particle's displacement, or of its velocity divided by omega, from the closed form.
template <class MakeStepper>
double oscillator_error(MakeStepper make, double h) {
  using O = Oscillator;
  const cloth::Scene scene(cloth::single_spring_params(O::K, O::D));
  cloth::ForceField field(scene);
  auto stepper = make(field);
  cloth::Vector x, v;
  cloth::single_spring_initial_state(scene, O::s0, x, v);
  const cloth::Vector rest = scene.initial_positions();
  const auto steps = std::llround(O::T / h);
  for (long long n = 0; n < steps; ++n) REQUIRE(stepper->step(h, x, v));
  const cloth::OscillatorState exact = cloth::single_spring_exact(O::K, O::D, O::m, O::s0, O::T);
  const double omega = std::sqrt(O::K / O::m);
  double error = 0;
  for (Eigen::Index i = 1; i < x.size(); i += 3)
    error = std::max({error, std::abs(x[i] - rest[i] - exact.s), std::abs(v[i] - exact.ds) / omega});
  return error;
}

}  // namespace cloth_test
