// Power iteration with a two-term fit per step (analysis/power_iteration.hpp).
#include "analysis/power_iteration.hpp"

#include <cmath>
#include <utility>

namespace cloth {

std::array<std::complex<double>, 2> quadratic_roots(double p, double q) {
  const std::complex<double> root = std::sqrt(std::complex<double>(p * p - 4 * q, 0.0));
  return {0.5 * (-p + root), 0.5 * (-p - root)};
}

PowerIterationResult dominant_eigenvalue(const LinearOperator& apply, Vector y0,
                                         const PowerIterationSettings& settings) {
  y0.normalize();
  Vector y1(y0.size()), y2(y0.size()), w(y0.size()), z(y0.size());
  PowerIterationResult result;
  double previous = 0;
  for (int it = 1; it <= settings.max_iterations; ++it) {
    apply(y0, y1);
    apply(y1, y2);
    result.iterations = it;
    const double y2_norm = y2.norm();
    if (y2_norm == 0) {  // A y0 = 0 or A^2 y0 = 0: nothing left to iterate on
      result.magnitude = y1.norm();
      result.dominant = result.magnitude;
      result.converged = true;
      break;
    }
    // The 2 x 2 matrix H of A on the orthonormal basis q1 = y0, q2 = w / |w| of span{y0, y1}, w = y1 - h11 y0;
    // A q2 = z / |w| with z = y2 - h11 y1. Its eigenvalues are the roots of the monic quadratic that minimises
    // |y2 + p y1 + q y0|, found here without forming the normal equations, which lose half the digits when y1
    // is nearly parallel to y0.
    const double h11 = y0.dot(y1);
    w = y1 - h11 * y0;
    const double h21 = w.norm();
    double estimate = 0;
    if (h21 > 1e-10 * y1.norm()) {
      z = y2 - h11 * y1;
      const double h12 = y0.dot(z) / h21, h22 = w.dot(z) / (h21 * h21);
      const auto roots = quadratic_roots(-(h11 + h22), h11 * h22 - h12 * h21);
      const auto top = std::abs(roots[0]) >= std::abs(roots[1]) ? roots[0] : roots[1];
      result.dominant = {top.real(), std::abs(top.imag())};
      estimate = std::abs(top);
    } else {
      estimate = std::abs(h11);  // y0 is an eigenvector to rounding: h11 its (real) eigenvalue
      result.dominant = h11;
    }
    result.magnitude = estimate;
    if (it % settings.check_every == 0) {
      if (std::abs(estimate - previous) <= settings.tolerance * estimate) {
        result.converged = true;
        break;
      }
      previous = estimate;
    }
    y0 = y2 / y2_norm;
  }
  return result;
}

}  // namespace cloth
