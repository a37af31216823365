// The cloth's right-hand side as a reader would first write it for a general ODE library: the state one flat
// std::vector (positions of the free particles, then their velocities), one plain loop over the springs, in any
// floating-point type (double for the straightforward Boost.Odeint program, long double for the reference).
// Only the topology (which particles a spring joins, rest lengths, pinned positions) is taken from the Scene.
// Chapter 6's plain_fabric.hpp, the peers' loop, adds the same terms in another order; the page says why the two
// are kept apart (ch08.md, "Why this loop and not Chapter 6's").
#pragma once

#include "model/scene.hpp"

#include <cmath>
#include <vector>

namespace ch08 {

template <class Real>
class PlainCloth {
 public:
  explicit PlainCloth(const cloth::Scene& scene)
      : free_(scene.free_count()),
        K_(scene.params().stiffness),
        D_(scene.params().damping),
        m_(scene.params().mass),
        g_(scene.params().gravity),
        force_(3 * static_cast<std::size_t>(scene.rest_positions().size() / 3)) {
    for (const cloth::Spring& s : scene.springs().springs) springs_.push_back({s.p, s.q, s.rest_length});
    const auto& rest = scene.rest_positions();
    for (Eigen::Index k = 3 * free_; k < rest.size(); ++k) pinned_.push_back(rest[k]);
  }

  /// y = (x, v) of the free particles, the initial state of the scene.
  static std::vector<Real> initial_state(const cloth::Scene& scene) {
    const Eigen::VectorXd x = scene.initial_positions(), v = scene.initial_velocities();
    std::vector<Real> y(static_cast<std::size_t>(x.size() + v.size()));
    for (Eigen::Index k = 0; k < x.size(); ++k) y[k] = x[k], y[x.size() + k] = v[k];
    return y;
  }

  // [plain_rhs]
  /// dy/dt = (v, f(x, v) / m): spring K (L0 - l) u and projected damping -D ((v_p - v_q) . u) u on each end,
  /// gravity on every free particle; the pinned particles do not move.
  void operator()(const std::vector<Real>& y, std::vector<Real>& dydt, double /*t*/) {
    const std::size_t n = 3 * static_cast<std::size_t>(free_);
    std::fill(force_.begin(), force_.end(), Real(0));
    for (const Link& s : springs_) {
      Real d[3], w[3];
      for (int k = 0; k < 3; ++k) {
        d[k] = position(y, s.p, k) - position(y, s.q, k);
        w[k] = velocity(y, s.p, k) - velocity(y, s.q, k);
      }
      const Real l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (l < Real(1e-12) * s.rest) continue;  // coincident ends: no direction, no force (as the project)
      const Real u[3] = {d[0] / l, d[1] / l, d[2] / l};
      const Real along = w[0] * u[0] + w[1] * u[1] + w[2] * u[2];
      const Real magnitude = Real(K_) * (s.rest - l) - Real(D_) * along;
      for (int k = 0; k < 3; ++k) {
        force_[3 * static_cast<std::size_t>(s.p) + k] += magnitude * u[k];
        force_[3 * static_cast<std::size_t>(s.q) + k] -= magnitude * u[k];
      }
    }
    for (std::size_t k = 0; k < n; ++k) {
      dydt[k] = y[n + k];
      dydt[n + k] = force_[k] / Real(m_) - (k % 3 == 2 ? Real(g_) : Real(0));
    }
  }
  // [plain_rhs]

 private:
  struct Link {
    int p, q;
    Real rest;
  };
  Real position(const std::vector<Real>& y, int slot, int k) const {
    return slot < free_ ? y[3 * static_cast<std::size_t>(slot) + k] : Real(pinned_[3 * static_cast<std::size_t>(slot - free_) + k]);
  }
  Real velocity(const std::vector<Real>& y, int slot, int k) const {
    return slot < free_ ? y[3 * static_cast<std::size_t>(free_ + slot) + k] : Real(0);
  }

  int free_;
  double K_, D_, m_, g_;
  std::vector<Link> springs_;
  std::vector<double> pinned_;
  std::vector<Real> force_;
};

}  // namespace ch08
