// The cloth as a reader would write it for an ODE library, sharing no code with the book's core: every particle's
// position and velocity in one array y = (x, v), a plain loop over the springs for y' = (v, f / m), and the same
// loop for the analytic Jacobian dy'/dy in compressed columns (for SUNDIALS' KLU). Pinned particles stay in the
// state with zero derivatives. The peer programs drive Boost.Odeint and SUNDIALS with it: Chapter 6's odeint peer
// (odeint_peer.cpp) and Chapter 10's. A library that takes the system by value (odeint's steppers) is given it by
// reference, std::cref(fabric): a copy carries the springs and the Jacobian's pattern, and odeint copies the system
// at every step.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace ch06 {

class PlainFabric {
 public:
  // M x N particles at (i d, j d, 0), corners pinned (or with `edge` the row j = N-1), structural, shear and
  // flexion springs of stiffness K with the projected damper D, particle mass m, gravity g, every free particle
  // starting at z velocity v0 plus, with `swing` w, a rigid turn w (N-1-j) d about the edge's line.
  PlainFabric(int M, int N, double d, double K, double D, double m, double g, double v0, bool edge = false,
              double swing = 0)
      : P_(M * N), N_(N), d_(d), K_(K), D_(D), m_(m), g_(g), v0_(v0), swing_(swing),
        pinned_(static_cast<std::size_t>(P_), false) {
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
    if (edge)
      for (int i = 0; i < M; ++i) pinned_[static_cast<std::size_t>(id(i, N - 1))] = true;
    else
      for (int c : {id(0, 0), id(M - 1, 0), id(0, N - 1), id(M - 1, N - 1)}) pinned_[static_cast<std::size_t>(c)] = true;
    rest_.assign(3 * static_cast<std::size_t>(P_), 0.0);
    for (int i = 0; i < M; ++i)
      for (int j = 0; j < N; ++j) rest_[3 * id(i, j)] = i * d, rest_[3 * id(i, j) + 1] = j * d;
    build_pattern();
  }

  [[nodiscard]] int size() const { return 6 * P_; }  // the length of y
  [[nodiscard]] int particles() const { return P_; }
  [[nodiscard]] long nonzeros() const { return static_cast<long>(row_.size()); }

  [[nodiscard]] std::vector<double> initial_state() const {
    std::vector<double> y(static_cast<std::size_t>(size()), 0.0);
    for (int p = 0; p < P_; ++p) {
      for (int k = 0; k < 3; ++k) y[3 * p + k] = rest_[3 * p + k];
      if (!pinned(p)) y[3 * (P_ + p) + 2] = v0_ + swing_ * (N_ - 1 - p % N_) * d_;
    }
    return y;
  }

  // a = f(x, v) / m, zero for the pinned particles.
  void acceleration(const double* x, const double* v, double* a) const {
    for (int p = 0; p < P_; ++p) a[3 * p] = 0, a[3 * p + 1] = 0, a[3 * p + 2] = -g_;
    for (const Spring& s : springs_) {
      double u[3], w = 0, l2 = 0;
      for (int k = 0; k < 3; ++k) u[k] = x[3 * s.p + k] - x[3 * s.q + k], l2 += u[k] * u[k];
      const double l = std::sqrt(l2);
      for (int k = 0; k < 3; ++k) u[k] /= l, w += (v[3 * s.p + k] - v[3 * s.q + k]) * u[k];
      const double magnitude = (K_ * (s.rest - l) - D_ * w) / m_;  // spring K (L0 - l) u, damper -D (w . u) u
      for (int k = 0; k < 3; ++k) a[3 * s.p + k] += magnitude * u[k], a[3 * s.q + k] -= magnitude * u[k];
    }
    for (int p = 0; p < P_; ++p)
      if (pinned(p))
        for (int k = 0; k < 3; ++k) a[3 * p + k] = 0;
  }

  // y' = (v, f / m), pinned particles held still.
  void rhs(const double* y, double* dydt) const {
    for (int p = 0; p < P_; ++p)
      for (int k = 0; k < 3; ++k) dydt[3 * p + k] = pinned(p) ? 0.0 : y[3 * (P_ + p) + k];
    acceleration(y, y + 3 * P_, dydt + 3 * P_);
  }

  // One symplectic Euler step in place, v += h a(x, v), then x += h v, with `a` as scratch of 3 P entries.
  void symplectic_euler_step(double h, std::vector<double>& y, std::vector<double>& a) const {
    double* x = y.data();
    double* v = x + 3 * P_;
    acceleration(x, v, a.data());
    for (int c = 0; c < 3 * P_; ++c) v[c] += h * a[static_cast<std::size_t>(c)], x[c] += h * v[c];
  }

  // odeint's form of the right-hand side.
  void operator()(const std::vector<double>& y, std::vector<double>& dydt, double /*t*/) const {
    rhs(y.data(), dydt.data());
  }

  // The compressed-column pattern of dy'/dy = [[0, I], [df/dx / m, df/dv / m]]: column c of either half has the
  // diagonal entry of the upper half (0 under x, 1 under v, stored either way so that I - gamma J has its diagonal)
  // and then the rows of the lower half that the particle's springs reach.
  [[nodiscard]] const std::vector<long>& column_starts() const { return start_; }
  [[nodiscard]] const std::vector<long>& rows() const { return row_; }

  // The Jacobian's values at y, in the pattern's order. For a spring with unit vector u, length l and relative
  // velocity w = v_p - v_q, the block of f_p by x_p is
  //   Bx = -K [(1 - L0/l) I + (L0/l) u u^T] - (D/l) [u w^T (I - u u^T) + (w . u)(I - u u^T)],
  // the block of f_p by v_p is Bv = -D u u^T, and by symmetry of the pair f_q takes -B of x_p and +B of x_q.
  // With `definite` (Choi and Ko 2002, the matrix the book's Newton uses): Bx = -K [max(0, 1 - L0/l)(I - u u^T)
  // + u u^T], a compressed spring's transverse term and the damper's d/dx dropped, so -Bx is positive
  // semi-definite.
  void jacobian(const double* y, double* values, bool definite = false) {
    const double* x = y;
    const double* v = y + 3 * P_;
    std::fill(values, values + nonzeros(), 0.0);
    for (int c = 3 * P_; c < 6 * P_; ++c)
      if (!pinned((c - 3 * P_) / 3)) values[start_[static_cast<std::size_t>(c)]] = 1;  // dx'/dv = I
    for (const Spring& s : springs_) {
      double u[3], w[3], wu = 0, l2 = 0;
      for (int k = 0; k < 3; ++k) u[k] = x[3 * s.p + k] - x[3 * s.q + k], l2 += u[k] * u[k];
      const double l = std::sqrt(l2);
      for (int k = 0; k < 3; ++k) u[k] /= l, w[k] = v[3 * s.p + k] - v[3 * s.q + k], wu += w[k] * u[k];
      double Bx[3][3], Bv[3][3], wP[3];  // wP = (I - u u^T) w
      for (int k = 0; k < 3; ++k) wP[k] = w[k] - wu * u[k];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          const double I = a == b ? 1.0 : 0.0, uu = u[a] * u[b];
          if (definite)
            Bx[a][b] = -K_ * (std::max(0.0, 1 - s.rest / l) * (I - uu) + uu);
          else
            Bx[a][b] = -K_ * ((1 - s.rest / l) * I + s.rest / l * uu) - D_ / l * (u[a] * wP[b] + wu * (I - uu));
          Bv[a][b] = -D_ * uu;
        }
      // Each spring adds its block to four 3 x 3 places of each half: (p, p), (q, p), (p, q), (q, q).
      const auto add = [&](int row_particle, int column_particle, double sign, int half, const double (*B)[3]) {
        if (pinned(row_particle)) return;  // a pinned particle's acceleration is held at zero
        for (int b = 0; b < 3; ++b) {
          const long first = first_row_index(half, column_particle, b, row_particle);
          for (int a = 0; a < 3; ++a) values[first + a] += sign * B[a][b] / m_;
        }
      };
      for (int half = 0; half < 2; ++half) {
        const double (*B)[3] = half == 0 ? Bx : Bv;
        add(s.p, s.p, +1, half, B), add(s.q, s.p, -1, half, B), add(s.p, s.q, -1, half, B), add(s.q, s.q, +1, half, B);
      }
    }
  }

  [[nodiscard]] bool pinned(int p) const { return pinned_[static_cast<std::size_t>(p)]; }

 private:
  struct Spring {
    int p, q;
    double rest;
  };

  // Where rows 3 row_particle .. +2 of the lower half start in column 3 column_particle + b of the given half.
  [[nodiscard]] long first_row_index(int half, int column_particle, int b, int row_particle) const {
    const int c = half * 3 * P_ + 3 * column_particle + b;
    const auto& near = neighbours_[static_cast<std::size_t>(column_particle)];
    const long k = std::lower_bound(near.begin(), near.end(), row_particle) - near.begin();
    return start_[static_cast<std::size_t>(c)] + 1 + 3 * k;
  }

  void build_pattern() {
    neighbours_.assign(static_cast<std::size_t>(P_), {});
    for (int p = 0; p < P_; ++p) neighbours_[static_cast<std::size_t>(p)].push_back(p);
    for (const Spring& s : springs_) {
      neighbours_[static_cast<std::size_t>(s.p)].push_back(s.q);
      neighbours_[static_cast<std::size_t>(s.q)].push_back(s.p);
    }
    for (auto& near : neighbours_) std::sort(near.begin(), near.end());
    start_.clear();
    row_.clear();
    for (int c = 0; c < 6 * P_; ++c) {
      start_.push_back(static_cast<long>(row_.size()));
      const int column_particle = (c % (3 * P_)) / 3;
      row_.push_back(c % (3 * P_));  // the upper half's diagonal entry
      for (int q : neighbours_[static_cast<std::size_t>(column_particle)])
        for (int a = 0; a < 3; ++a) row_.push_back(3 * P_ + 3 * q + a);
    }
    start_.push_back(static_cast<long>(row_.size()));
  }

  int P_, N_;
  double d_, K_, D_, m_, g_, v0_, swing_;
  std::vector<bool> pinned_;
  std::vector<double> rest_;
  std::vector<Spring> springs_;
  std::vector<std::vector<int>> neighbours_;  // per particle: itself and the particles its springs reach, sorted
  std::vector<long> start_, row_;
};

}  // namespace ch06
