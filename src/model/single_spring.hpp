// A linear oscillator built from the cloth model itself, with a closed-form solution: Chapter 2 measures explicit
// Euler's energy growth on it, Chapter 3 and the tests measure observed orders of accuracy and stability limits.
#pragma once

#include "model/force_field.hpp"

#include <cmath>

namespace cloth {

/// A 2 x 2 grid with its edge j = 1 pinned and structural springs only, no gravity: the two free particles hang
/// from the pinned edge by one spring each and are joined to each other by a third. Displace both by the same
/// s along y and the joining spring stays at rest length, while each hanging spring is stretched along its own
/// axis. For |s| < d the force -K s - D s' is then exactly linear: every free particle is a damped oscillator
///   m s'' + D s' + K s = 0,   omega^2 = K / m,   2 zeta omega = D / m.
inline SceneParams single_spring_params(double K, double D) {
  SceneParams p;
  p.grid = Grid{2, 2, 0.1};
  p.stiffness = K;
  p.damping = D;
  p.families = FamilySet::only(SpringFamily::structural);
  p.pins = PinSet::edge;
  p.initial_velocity_z = 0;
  p.gravity = 0;
  return p;
}

/// The initial state of the oscillator: every free particle displaced by s0 along y (away from the pins when
/// s0 < 0), at rest.
inline void single_spring_initial_state(const Scene& scene, double s0, Vector& x, Vector& v) {
  x = scene.initial_positions();
  v = Vector::Zero(x.size());
  for (Eigen::Index k = 1; k < x.size(); k += 3) x[k] += s0;
}

/// The closed-form displacement s(t) and velocity s'(t) of the underdamped oscillator (zeta < 1) that starts at
/// s(0) = s0 at rest: s = e^{-zeta omega t} s0 (cos omega_d t + zeta omega / omega_d sin omega_d t),
/// s' = -s0 omega^2 / omega_d e^{-zeta omega t} sin omega_d t, omega_d = omega sqrt(1 - zeta^2).
struct OscillatorState {
  double s, ds;
};
inline OscillatorState single_spring_exact(double K, double D, double m, double s0, double t) {
  const double omega = std::sqrt(K / m);
  const double alpha = D / (2 * m);  // zeta omega
  const double omega_d = std::sqrt(omega * omega - alpha * alpha);
  const double decay = std::exp(-alpha * t);
  return {decay * s0 * (std::cos(omega_d * t) + alpha / omega_d * std::sin(omega_d * t)),
          -decay * s0 * omega * omega / omega_d * std::sin(omega_d * t)};
}

}  // namespace cloth
