// Stability functions and amplification factors: the linear theory that predicts when each method is stable.
#include "analysis/stability_function.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace cloth {

Complex stability_function(const ButcherTableau& tableau, Complex z) {
  const int s = tableau.stages();
  const Eigen::MatrixXcd I_minus_zA = Eigen::MatrixXcd::Identity(s, s) - z * tableau.A.cast<Complex>();
  // The stage values of y' = lambda y with y0 = 1 solve (I - z A) Y = 1; then R = 1 + z b^T Y.
  const Eigen::VectorXcd Y = I_minus_zA.partialPivLu().solve(Eigen::VectorXcd::Ones(s));
  return 1.0 + z * tableau.b.cast<Complex>().dot(Y);
}

std::vector<double> stability_polynomial(const ButcherTableau& tableau) {
  const int s = tableau.stages();
  std::vector<double> r = {1.0};
  Eigen::VectorXd power = Eigen::VectorXd::Ones(s);  // A^{k-1} 1
  for (int k = 1; k <= s; ++k) {
    r.push_back(tableau.b.dot(power));
    power = tableau.A * power;
  }
  return r;
}

double stability_at_infinity(const ButcherTableau& tableau) {
  // R(z) = R_inf + c1 / z + c2 / z^2 + ...: at z, 2z and 4z, two Richardson levels remove c1 and c2. |z| = 1e4
  // balances the rest (c3 / z^3 ~ 1e-12) against rounding (1 + z b^T Y cancels terms of size |z|, ~1e-12).
  const double z = -1e4;
  const double r1 = stability_function(tableau, z).real(), r2 = stability_function(tableau, 2 * z).real(),
               r4 = stability_function(tableau, 4 * z).real();
  // A polynomial of degree k >= 1 (an explicit method) grows by 4^k from z to 4z; a bounded R barely moves.
  if (std::abs(r4) > 2 * std::abs(r1) + 1) return INFINITY;
  const double once_12 = 2 * r2 - r1, once_24 = 2 * r4 - r2;
  return (4 * once_24 - once_12) / 3;
}

double imaginary_axis_maximum(const ButcherTableau& tableau, int samples) {
  const double quarter_turn = std::acos(0.0);
  double largest = std::abs(stability_at_infinity(tableau));
  for (int k = 0; k < samples; ++k) {
    const double y = std::tan(quarter_turn * k / samples);
    largest = std::max(largest, std::abs(stability_function(tableau, Complex(0, y))));
  }
  return largest;
}

bool a_stable(const ButcherTableau& tableau) {
  const Eigen::VectorXcd eigenvalues = tableau.A.eigenvalues();
  for (const Complex& lambda : eigenvalues)
    if (std::abs(lambda) > 1e-14 && !(lambda.real() > 1e-14)) return false;  // a pole 1/lambda with Re <= 0
  return imaginary_axis_maximum(tableau) <= 1 + 1e-12;
}

Complex implicit_euler_stability(Complex z) { return 1.0 / (1.0 - z); }

double symplectic_euler_amplification(Complex z1, Complex z2) {
  // h^2 a = -z1 z2 and h b = z1 + z2 are real when z1, z2 are a conjugate pair or both real.
  const double h2a = -(z1 * z2).real();
  const double hb = (z1 + z2).real();
  const double trace = 2 + h2a + hb;
  const double det = 1 + hb;
  // Eigenvalues of the 2 x 2 matrix: mu^2 - trace mu + det = 0. The discriminant trace^2 - 4 det is expanded as
  // 4 h^2 a + (h^2 a + h b)^2, because forming it from trace ~ 2 and det ~ 1 cancels for slow modes and would
  // report growth of 1e-8 per step where there is none.
  const double disc = 4 * h2a + (h2a + hb) * (h2a + hb);
  if (disc < 0) return std::sqrt(std::abs(det));  // a conjugate pair: |mu|^2 = det
  const double root = std::sqrt(disc);
  return std::max(std::abs(0.5 * (trace + root)), std::abs(0.5 * (trace - root)));
}

bool symplectic_euler_stable(double h2a, double hb) {
  const double det = 1 + hb;
  const double trace = 2 + h2a + hb;
  return std::abs(det) <= 1 && std::abs(trace) <= 1 + det;
}

double stability_limit_along(const std::function<bool(double)>& stable, double t_max, int scan, int iterations) {
  double lo = 0;
  double hi = t_max;
  bool left = false;
  for (int k = 1; k <= scan; ++k) {
    const double t = t_max * k / scan;
    if (!stable(t)) {
      hi = t;
      left = true;
      break;
    }
    lo = t;
  }
  if (!left) return t_max;
  for (int k = 0; k < iterations; ++k) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace cloth
