// Explicit (forward) Euler, Chapter 2: x1 = x0 + h v0, v1 = v0 + h M^{-1} f(x0, v0). One force evaluation per
// step; stability function R(z) = 1 + z, so an undamped oscillator gains energy every step.
#pragma once

#include "integrators/stepper.hpp"

namespace cloth {

class ExplicitEuler final : public Stepper {
 public:
  explicit ExplicitEuler(ForceField& field) : Stepper(field), a_(field.dof_count()) {}
  [[nodiscard]] std::string name() const override { return "explicit_euler"; }
  bool step(double h, Vector& x, Vector& v) override {
    // [explicit_euler_step]
    field_.acceleration(x, v, a_);  // a = M^{-1} f(x0, v0)
    x += h * v;                     // x1 = x0 + h v0
    v += h * a_;                    // v1 = v0 + h a
    // [explicit_euler_step]
    ++counters_.rhs_evaluations;
    ++counters_.steps;
    return true;
  }

 private:
  Vector a_;
};

}  // namespace cloth
