// The fastest rates of the cloth that limit explicit methods (Chapters 2, 3 and 5): the highest angular frequency
// of the springs and the fastest damping rate, each the largest eigenvalue of a symmetric matrix found by power
// iteration on the model's own sparse Jacobians.
#pragma once

#include "model/force_field.hpp"
#include "analysis/power_iteration.hpp"

#include <cmath>
#include <utility>

namespace cloth {

/// Largest eigenvalue of -M^{-1} J for a symmetric negative semidefinite J, by power iteration
/// (analysis/power_iteration.hpp). The top modes of the cloth lie close together, which the iteration's two-term fit
/// copes with; it runs until the estimate changes by less than 1e-9 relative over 100 iterations (each costs two
/// sparse products).
inline double largest_rate(const SparseMatrix& J, double mass) {
  const LinearOperator minus_inverse_mass_J = [&](const Vector& y, Vector& out) { out = -(J * y) / mass; };
  Vector start = Vector::Ones(J.rows()) + Vector::LinSpaced(J.rows(), 0.0, 1.0);  // not orthogonal to the top mode
  const PowerIterationResult top = dominant_eigenvalue(minus_inverse_mass_J, std::move(start), {1e-9, 100, 20000});
  return top.dominant.real() > 0 ? top.magnitude : 0.0;
}

/// omega_max of the cloth linearised at its rest state: omega_max^2 = largest eigenvalue of -M^{-1} df/dx there
/// (every spring at rest length, so -df/dx is positive semidefinite). Explicit Euler multiplies that mode's
/// energy by 1 + (h omega_max)^2 per step.
inline double fastest_rest_frequency(ForceField& field) {
  const Scene& scene = field.scene();
  const Vector x = scene.initial_positions();
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, Vector::Zero(x.size()), dfdx, dfdv);
  return std::sqrt(largest_rate(dfdx, scene.params().mass));
}

// [fastest_damping_rate]
/// The fastest damping rate c_max at (x, v): the largest eigenvalue of -M^{-1} df/dv (the projected damper gives
/// df/dv = -D sum u u^T over springs, symmetric negative semidefinite). A mode damped at rate c is a real
/// eigenvalue -c of the ODE, and an explicit method is stable on it only while h c stays inside its stability
/// interval on the negative real axis: 2 for explicit Euler, 2.785 for RK4.
inline double fastest_damping_rate(ForceField& field, const Vector& x, const Vector& v) {
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, v, dfdx, dfdv);
  return largest_rate(dfdv, field.scene().params().mass);
}
// [fastest_damping_rate]

}  // namespace cloth
