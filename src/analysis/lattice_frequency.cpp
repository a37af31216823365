// omega_max of the flat square lattice from its dispersion relation (see lattice_frequency.hpp).
#include "analysis/lattice_frequency.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cloth {

namespace {

// The larger eigenvalue of the dynamical matrix times m, at the wave vector (a, b) / d.
double largest_squared_frequency(const LatticeSprings& s, double a, double b) {
  double xx = 0, xy = 0, yy = 0;
  const auto bond = [&](double k, double rx, double ry) {
    const double l2 = rx * rx + ry * ry;
    const double c = 2 * k * (1 - std::cos(a * rx + b * ry)) / l2;  // 2 k (1 - cos q.r) u u^T, u = r / |r|
    xx += c * rx * rx, xy += c * rx * ry, yy += c * ry * ry;
  };
  bond(s.structural, 1, 0), bond(s.structural, 0, 1);
  bond(s.shear, 1, 1), bond(s.shear, 1, -1);
  bond(s.flexion, 2, 0), bond(s.flexion, 0, 2);
  const double mean = (xx + yy) / 2, half_gap = std::hypot((xx - yy) / 2, xy);
  return mean + half_gap;
}

}  // namespace

double lattice_fastest_frequency(const LatticeSprings& s) {
  // A coarse scan of [0, pi]^2 locates the maximum; two finer scans around it pin it to ~1e-9 relative.
  double best = 0, best_a = 0, best_b = 0, width = std::numbers::pi;
  double centre_a = width / 2, centre_b = width / 2;
  for (int pass = 0; pass < 3; ++pass) {
    constexpr int n = 200;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const double a = std::clamp(centre_a + width * (i - n / 2.0) / n, 0.0, std::numbers::pi);
        const double b = std::clamp(centre_b + width * (j - n / 2.0) / n, 0.0, std::numbers::pi);
        const double w2 = largest_squared_frequency(s, a, b);
        if (w2 > best) best = w2, best_a = a, best_b = b;
      }
    centre_a = best_a, centre_b = best_b;
    width = pass == 0 ? 2 * std::numbers::pi / 200 : width / 50;
  }
  return std::sqrt(best / s.mass);
}

}  // namespace cloth
