// Symplectic (semi-implicit) Euler: v1 = v0 + h M^{-1} f(x0, v0), then x1 = x0 + h v1. As cheap as explicit
// Euler, but for undamped springs it keeps the energy bounded when h omega < 2: the explicit method cloth
// practitioners use. It is a partitioned method, explicit Euler for v and implicit Euler for x (two different
// tableaus), so the one-tableau Runge-Kutta engine cannot run it and it keeps this stepper of its own.
#pragma once

#include "integrators/stepper.hpp"

namespace cloth {

class SymplecticEuler final : public Stepper {
 public:
  explicit SymplecticEuler(ForceField& field) : Stepper(field), a_(field.dof_count()) {}
  [[nodiscard]] std::string name() const override { return "symplectic_euler"; }
  bool step(double h, Vector& x, Vector& v) override {
    // The two updates share one pass over the state (written as two Eigen lines they would be two passes).
    // [symplectic_euler_step]
    field_.acceleration(x, v, a_);  // a = M^{-1} f(x0, v0)
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      v[i] += h * a_[i];  // v1 = v0 + h a
      x[i] += h * v[i];   // x1 = x0 + h v1: the new velocity moves the particles
    }
    // [symplectic_euler_step]
    ++counters_.rhs_evaluations;
    ++counters_.steps;
    return true;
  }

 private:
  Vector a_;
};

}  // namespace cloth
