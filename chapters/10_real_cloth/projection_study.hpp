// The curtain as a reader would write it for an ODE library, sharing no code with the book's core: the peer of
// Chapter 10's study of inextensible cloth (projection_study.cpp). Every particle's position and velocity in one
// array y = (x, v), the edge j = N-1 pinned (its particles keep zero derivatives), and one plain loop over the
// structural, shear and flexion springs for y' = (v, f / m), with the projected damper -D ((v_p - v_q) . u) u.
#pragma once

#include <cmath>
#include <vector>

namespace ch10 {

class PlainCurtain {
 public:
  // N x N particles at (i d, j d, 0), every spring of stiffness K and damping D, particle mass m, gravity g.
  PlainCurtain(int N, double d, double K, double D, double m, double g)
      : P_(N * N), N_(N), K_(K), D_(D), m_(m), g_(g) {
    const auto id = [N](int i, int j) { return i * N + j; };
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        const auto spring = [&](int i2, int j2) {
          if (i2 < N && j2 >= 0 && j2 < N) springs_.push_back({id(i, j), id(i2, j2), d * std::hypot(i2 - i, j2 - j)});
        };
        spring(i + 1, j), spring(i, j + 1);          // structural
        spring(i + 1, j + 1), spring(i + 1, j - 1);  // shear
        spring(i + 2, j), spring(i, j + 2);          // flexion
      }
    rest_.assign(3 * static_cast<std::size_t>(P_), 0.0);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) rest_[3 * id(i, j)] = i * d, rest_[3 * id(i, j) + 1] = j * d;
  }

  [[nodiscard]] int size() const { return 6 * P_; }  // the length of y
  [[nodiscard]] int particles() const { return P_; }
  [[nodiscard]] bool pinned(int p) const { return p % N_ == N_ - 1; }

  // Flat and at rest.
  [[nodiscard]] std::vector<double> initial_state() const {
    std::vector<double> y(static_cast<std::size_t>(size()), 0.0);
    for (int c = 0; c < 3 * P_; ++c) y[static_cast<std::size_t>(c)] = rest_[static_cast<std::size_t>(c)];
    return y;
  }

  // a = f(x, v) / m, zero on the pinned edge.
  void acceleration(const double* x, const double* v, double* a) const {
    for (int p = 0; p < P_; ++p) a[3 * p] = 0, a[3 * p + 1] = 0, a[3 * p + 2] = -g_;
    for (const Spring& s : springs_) {
      double u[3], w = 0, l2 = 0;
      for (int k = 0; k < 3; ++k) u[k] = x[3 * s.p + k] - x[3 * s.q + k], l2 += u[k] * u[k];
      const double l = std::sqrt(l2);
      for (int k = 0; k < 3; ++k) u[k] /= l, w += (v[3 * s.p + k] - v[3 * s.q + k]) * u[k];
      const double magnitude = (K_ * (s.rest - l) - D_ * w) / m_;
      for (int k = 0; k < 3; ++k) a[3 * s.p + k] += magnitude * u[k], a[3 * s.q + k] -= magnitude * u[k];
    }
    for (int p = N_ - 1; p < P_; p += N_) a[3 * p] = 0, a[3 * p + 1] = 0, a[3 * p + 2] = 0;
  }

  // y' = (v, a): odeint's form of the right-hand side.
  void operator()(const std::vector<double>& y, std::vector<double>& dydt, double /*t*/) const {
    const double* x = y.data();
    const double* v = x + 3 * P_;
    for (int c = 0; c < 3 * P_; ++c) dydt[static_cast<std::size_t>(c)] = v[c];
    acceleration(x, v, dydt.data() + 3 * P_);
  }

  // One symplectic Euler step in place: v += h a(x, v), then x += h v.
  void symplectic_euler_step(double h, std::vector<double>& y, std::vector<double>& a) const {
    double* x = y.data();
    double* v = x + 3 * P_;
    acceleration(x, v, a.data());
    for (int c = 0; c < 3 * P_; ++c) v[c] += h * a[static_cast<std::size_t>(c)], x[c] += h * v[c];
  }

 private:
  struct Spring {
    int p, q;
    double rest;
  };
  int P_, N_;
  double K_, D_, m_, g_;
  std::vector<double> rest_;
  std::vector<Spring> springs_;
};

}  // namespace ch10
