// The fastest rates of the cloth that limit explicit methods (Chapters 2, 3 and 5): the highest angular frequency
// of the springs and the fastest damping rate, each the largest eigenvalue of a symmetric matrix, found by the
// Lanczos method on the model's own sparse Jacobians.
#pragma once

#include "model/force_field.hpp"

#include <cmath>

namespace cloth {

/// Largest eigenvalue of -M^{-1} J for a symmetric negative semidefinite J and equal particle masses, by the
/// implicitly restarted Lanczos method (Spectra's SymEigsSolver; Lehoucq & Sorensen 1996). The cloth's top modes
/// lie close together, which slows a power iteration to thousands of sparse products; Lanczos separates them in
/// about a hundred. Accurate to about 1e-12 relative; 0 for J = 0.
double largest_rate(const SparseMatrix& J, double mass);

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
/// df/dv = -D sum u u^T over springs, symmetric negative semidefinite). A mode s'' = -omega^2 s - c s' damped at
/// rate c > 2 omega has the real eigenvalues -c/2 +- sqrt(c^2/4 - omega^2), the fast one -c + omega^2/c + ...,
/// which tends to -c as c/omega grows: h c measures it against an explicit method's stability interval on the
/// negative real axis (2 for explicit Euler, 2.785 for RK4) with a margin of order (h omega)^2.
inline double fastest_damping_rate(ForceField& field, const Vector& x, const Vector& v) {
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, v, dfdx, dfdv);
  return largest_rate(dfdv, field.scene().params().mass);
}
// [fastest_damping_rate]

}  // namespace cloth
