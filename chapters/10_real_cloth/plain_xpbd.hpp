// XPBD as a reader would write it from Macklin, Müller and Chentanez (2016), sharing no code with the book's core:
// plain arrays, every spring a compliant distance constraint (compliance 1/K, the damper D as their Rayleigh
// damping), `substeps` substeps per step, each an inertial prediction and `iterations` Gauss-Seidel sweeps.
// Chapter 10's map runs it beside the book's registry method `xpbd` on the same fabric.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace ch10 {

class PlainXpbd {
 public:
  // The fabric of PlainFabric: M x N particles at (i d, j d, 0), corners (or with `edge` the row j = N-1) pinned,
  // structural, shear and flexion springs of stiffness K with damper D, mass m, gravity g, a swing w about the edge.
  PlainXpbd(int M, int N, double d, double K, double D, double m, double g, bool edge, double swing)
      : P_(M * N), K_(K), D_(D), w_(1 / m), g_(g), x_(3 * static_cast<std::size_t>(P_)), v_(x_.size(), 0.0) {
    const auto id = [N](int i, int j) { return i * N + j; };
    for (int i = 0; i < M; ++i)
      for (int j = 0; j < N; ++j) {
        const auto spring = [&](int i2, int j2) {
          if (i2 < M && j2 >= 0 && j2 < N) springs_.push_back({id(i, j), id(i2, j2), d * std::hypot(i2 - i, j2 - j)});
        };
        spring(i + 1, j), spring(i, j + 1), spring(i + 1, j + 1), spring(i + 1, j - 1), spring(i + 2, j), spring(i, j + 2);
        const bool pinned = edge ? j == N - 1 : (i == 0 || i == M - 1) && (j == 0 || j == N - 1);
        inverse_mass_.push_back(pinned ? 0.0 : w_);
        x_[3 * id(i, j)] = i * d, x_[3 * id(i, j) + 1] = j * d, x_[3 * id(i, j) + 2] = 0;
        if (!pinned) v_[3 * id(i, j) + 2] = swing * (N - 1 - j) * d;
      }
    previous_ = x_;
    lambda_.assign(springs_.size(), 0.0);
  }

  // One step of h: `substeps` substeps of s = h / substeps.
  void step(double h, int substeps, int iterations) {
    const double s = h / substeps;
    for (int k = 0; k < substeps; ++k) substep(s, iterations);
  }

  [[nodiscard]] const std::vector<double>& positions() const { return x_; }

 private:
  struct Spring {
    int p, q;
    double rest;
  };

  void substep(double s, int iterations) {
    previous_ = x_;
    for (int p = 0; p < P_; ++p)
      if (inverse_mass_[p] > 0) {
        v_[3 * p + 2] -= g_ * s;
        for (int k = 0; k < 3; ++k) x_[3 * p + k] += s * v_[3 * p + k];
      }
    std::fill(lambda_.begin(), lambda_.end(), 0.0);
    const double alpha = 1 / (K_ * s * s);  // compliance 1/K over the substep squared
    const double gamma = D_ / (K_ * s);     // alpha~ beta~ / s with beta~ = s^2 D (Macklin et al. 2016, eq. 26)
    for (int sweep = 0; sweep < iterations; ++sweep)
      for (std::size_t c = 0; c < springs_.size(); ++c) {
        const Spring& sp = springs_[c];
        double u[3], l2 = 0, rate = 0;
        for (int k = 0; k < 3; ++k) u[k] = x_[3 * sp.p + k] - x_[3 * sp.q + k], l2 += u[k] * u[k];
        const double l = std::sqrt(l2);
        for (int k = 0; k < 3; ++k) {
          u[k] /= l;
          rate += u[k] * ((x_[3 * sp.p + k] - previous_[3 * sp.p + k]) - (x_[3 * sp.q + k] - previous_[3 * sp.q + k]));
        }
        const double wp = inverse_mass_[sp.p], wq = inverse_mass_[sp.q];
        const double dlambda = (-(l - sp.rest) - alpha * lambda_[c] - gamma * rate) / ((1 + gamma) * (wp + wq) + alpha);
        lambda_[c] += dlambda;
        for (int k = 0; k < 3; ++k) x_[3 * sp.p + k] += wp * dlambda * u[k], x_[3 * sp.q + k] -= wq * dlambda * u[k];
      }
    for (std::size_t k = 0; k < x_.size(); ++k) v_[k] = (x_[k] - previous_[k]) / s;
  }

  int P_;
  double K_, D_, w_, g_;
  std::vector<double> x_, v_, previous_, lambda_, inverse_mass_;
  std::vector<Spring> springs_;
};

}  // namespace ch10
