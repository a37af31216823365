// One generic explicit Runge-Kutta engine that runs any valid Butcher tableau (Chapter 3), with its stage
// storage allocated once.
#pragma once

#include "integrators/butcher_tableau.hpp"
#include "integrators/stepper.hpp"

#include <vector>

namespace cloth {

/// For y = (x, v) and y' = (v, M^{-1} f(x, v)) the stage derivative is k_i = (V_i, a(X_i, V_i)), so the stage
/// velocities V_i double as the position slopes and only V_i and a_i are stored.
class ExplicitRungeKutta final : public Stepper {
 public:
  /// `tableau` must pass validate().
  ExplicitRungeKutta(ForceField& field, ButcherTableau tableau);
  [[nodiscard]] std::string name() const override { return tableau_.name; }
  [[nodiscard]] const ButcherTableau& tableau() const { return tableau_; }
  bool step(double h, Vector& x, Vector& v) override;

 private:
  ButcherTableau tableau_;
  std::vector<Vector> stage_v_;  // V_i, for the stages that have one of their own
  std::vector<const Vector*> V_;  // V_i itself: &stage_v_[i], or &v when row i of A is zero (then V_i = v)
  std::vector<Vector> stage_a_;  // a_i = M^{-1} f(X_i, V_i)
  Vector stage_x_;               // X_i, needed only while a_i is evaluated
  Vector sum_v_, sum_a_;         // sum_i b_i V_i and sum_i b_i a_i
  int only_stage_ = -1;          // i when b = e_i (explicit Euler, the midpoint rule): the step is stage i's
};

}  // namespace cloth
