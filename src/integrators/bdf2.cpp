// BDF2: two steps of history, one stage equation per step.
#include "integrators/bdf2.hpp"

namespace cloth {

Bdf2::Bdf2(ForceField& field, NewtonSettings settings) : NewtonStepper(field, settings) {
  const int n = field.dof_count();
  x_previous_.resize(n), v_previous_.resize(n), x_last_.resize(n), v_last_.resize(n);
  x_tilde_.resize(n), v_tilde_.resize(n), V_.resize(n);
}

std::string Bdf2::name() const { return "bdf2"; }

bool Bdf2::step(double h, Vector& x, Vector& v) {
  newton_.begin_step();
  // The formula's coefficients hold for a constant step on the trajectory this stepper produced.
  const bool continuing = have_history_ && h == h_last_ && x == x_last_ && v == v_last_;
  double gamma = h;
  // [bdf2_step]
  if (continuing) {
    x_tilde_ = (4.0 / 3) * x - (1.0 / 3) * x_previous_;
    v_tilde_ = (4.0 / 3) * v - (1.0 / 3) * v_previous_;
    gamma = 2.0 / 3 * h;
    V_ = 2 * v - v_previous_;  // the guess: v extrapolated linearly
  } else {
    x_tilde_ = x;  // the starting step: backward Euler
    v_tilde_ = v;
    V_ = v;
  }
  // [bdf2_step]
  if (!newton_.solve(x_tilde_, v_tilde_, gamma, V_, false)) {
    failure_ = newton_.failure();
    if (!continuing) failure_.reason = "starting backward Euler step: " + failure_.reason;
    return false;
  }
  x_previous_ = x;
  v_previous_ = v;
  x = newton_.position();
  v = V_;
  x_last_ = x;
  v_last_ = v;
  h_last_ = h;
  have_history_ = true;
  ++counters_.steps;
  return true;
}

}  // namespace cloth
