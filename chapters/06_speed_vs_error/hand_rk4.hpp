// The classical RK4 step and the explicit Euler step written out by hand on the same ForceField: the yardsticks
// the generic tableau engine (integrators/explicit_runge_kutta) is timed against in Chapter 6. Not used for
// anything else.
#pragma once

#include "integrators/stepper.hpp"

namespace ch06 {

class HandRK4 final : public cloth::Stepper {
 public:
  explicit HandRK4(cloth::ForceField& field)
      : Stepper(field), xs_(field.dof_count()), a1_(field.dof_count()),
        a2_(field.dof_count()), a3_(field.dof_count()), a4_(field.dof_count()), v2_(field.dof_count()),
        v3_(field.dof_count()), v4_(field.dof_count()) {}
  [[nodiscard]] std::string name() const override { return "rk4_hand"; }
  bool step(double h, cloth::Vector& x, cloth::Vector& v) override {
    // k1 = (v, a(x, v)), k2 = (v2, a(x + h/2 v, v2)) with v2 = v + h/2 a1, and so on (Kutta 1901).
    field_.acceleration(x, v, a1_);
    xs_ = x + 0.5 * h * v;
    v2_ = v + 0.5 * h * a1_;
    field_.acceleration(xs_, v2_, a2_);
    xs_ = x + 0.5 * h * v2_;
    v3_ = v + 0.5 * h * a2_;
    field_.acceleration(xs_, v3_, a3_);
    xs_ = x + h * v3_;
    v4_ = v + h * a3_;
    field_.acceleration(xs_, v4_, a4_);
    x += (h / 6) * (v + 2 * v2_ + 2 * v3_ + v4_);
    v += (h / 6) * (a1_ + 2 * a2_ + 2 * a3_ + a4_);
    counters_.rhs_evaluations += 4;
    ++counters_.steps;
    return true;
  }

 private:
  cloth::Vector xs_, a1_, a2_, a3_, a4_, v2_, v3_, v4_;
};

/// Explicit Euler as Chapter 2 writes it: x += h v, v += h a(x, v).
class HandExplicitEuler final : public cloth::Stepper {
 public:
  explicit HandExplicitEuler(cloth::ForceField& field) : Stepper(field), a_(field.dof_count()) {}
  [[nodiscard]] std::string name() const override { return "explicit_euler_hand"; }
  bool step(double h, cloth::Vector& x, cloth::Vector& v) override {
    field_.acceleration(x, v, a_);
    x += h * v;
    v += h * a_;
    ++counters_.rhs_evaluations;
    ++counters_.steps;
    return true;
  }

 private:
  cloth::Vector a_;
};

}  // namespace ch06
