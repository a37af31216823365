// The program a reader would write with Boost.Odeint and nothing else: the report's cloth as one
// std::vector<double> state (positions, then velocities, of every particle), a plain loop over the springs for
// the forces, and odeint's classical runge_kutta4 (Ahnert & Mulansky 2011). Chapter 6 times it against the
// core; it shares no code with the core, so that the comparison is with what the core replaces.
#pragma once

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace ch06 {

class PlainOdeintCloth {
 public:
  using State = std::vector<double>;

  // The report scene: M x N particles at (i d, j d, 0), four corners pinned, structural, shear and flexion springs
  // of stiffness K and projected damping D, gravity g, every free particle falling at v0.
  PlainOdeintCloth(int M, int N, double d, double K, double D, double m, double g, double v0)
      : P_(M * N), K_(K), D_(D), m_(m), g_(g), v0_(v0), pinned_(P_, false) {
    const auto id = [N](int i, int j) { return i * N + j; };
    for (int i = 0; i < M; ++i)
      for (int j = 0; j < N; ++j) {
        const auto spring = [&](int i2, int j2) {
          if (i2 < M && j2 >= 0 && j2 < N) springs_.push_back({id(i, j), id(i2, j2), d * std::hypot(i2 - i, j2 - j)});
        };
        spring(i + 1, j), spring(i, j + 1);          // structural
        spring(i + 1, j + 1), spring(i + 1, j - 1);  // shear
        spring(i + 2, j), spring(i, j + 2);          // flexion
      }
    for (int c : {id(0, 0), id(M - 1, 0), id(0, N - 1), id(M - 1, N - 1)}) pinned_[c] = true;
    rest_.resize(3 * P_);
    for (int i = 0; i < M; ++i)
      for (int j = 0; j < N; ++j) rest_[3 * id(i, j)] = i * d, rest_[3 * id(i, j) + 1] = j * d;
  }

  [[nodiscard]] State initial_state() const {
    State y(6 * P_, 0.0);
    for (int p = 0; p < P_; ++p) {
      for (int k = 0; k < 3; ++k) y[3 * p + k] = rest_[3 * p + k];
      if (!pinned_[p]) y[3 * (P_ + p) + 2] = v0_;
    }
    return y;
  }

  // dy/dt = (v, f / m), with pinned particles held still.
  void operator()(const State& y, State& dydt, double /*t*/) const {
    const double* x = y.data();
    const double* v = y.data() + 3 * P_;
    double* dx = dydt.data();
    double* a = dydt.data() + 3 * P_;
    for (int p = 0; p < P_; ++p) {
      for (int k = 0; k < 3; ++k) dx[3 * p + k] = v[3 * p + k], a[3 * p + k] = 0;
      a[3 * p + 2] = -g_;
    }
    for (const Spring& s : springs_) {
      double e[3], dv = 0, l2 = 0;
      for (int k = 0; k < 3; ++k) e[k] = x[3 * s.p + k] - x[3 * s.q + k], l2 += e[k] * e[k];
      const double l = std::sqrt(l2);
      for (int k = 0; k < 3; ++k) e[k] /= l, dv += (v[3 * s.p + k] - v[3 * s.q + k]) * e[k];
      const double magnitude = (K_ * (s.rest - l) - D_ * dv) / m_;  // spring K (L0 - l) u, damper -D (dv . u) u
      for (int k = 0; k < 3; ++k) a[3 * s.p + k] += magnitude * e[k], a[3 * s.q + k] -= magnitude * e[k];
    }
    for (int p = 0; p < P_; ++p)
      if (pinned_[p])
        for (int k = 0; k < 3; ++k) dx[3 * p + k] = 0, a[3 * p + k] = 0;
  }

  // Integrates from t = 0 to T with fixed steps h; returns the final state. odeint takes the system by value,
  // so it is passed by reference (std::ref) rather than copying the springs at every step.
  [[nodiscard]] State run(double h, double T) const {
    State y = initial_state();
    boost::numeric::odeint::runge_kutta4<State> rk4;
    const long steps = std::lround(T / h);
    for (long n = 0; n < steps; ++n) rk4.do_step(std::cref(*this), y, static_cast<double>(n) * h, h);
    return y;
  }

  // The lowest z of any particle in a state.
  [[nodiscard]] double lowest_z(const State& y) const {
    double z = INFINITY;
    for (int p = 0; p < P_; ++p) z = std::min(z, y[3 * p + 2]);
    return z;
  }

 private:
  struct Spring {
    int p, q;
    double rest;
  };
  int P_;
  double K_, D_, m_, g_, v0_;
  std::vector<bool> pinned_;
  std::vector<double> rest_;
  std::vector<Spring> springs_;
};

}  // namespace ch06
