// Spring, damping and gravity forces (MODEL.md), their energies, and their analytic Jacobians refilled in a
// sparsity pattern built once. The spring loops are the hot loops of every chapter: they read springs
// contiguously, branch on the damping law once per family (a template), and allocate nothing.
#include "cloth/force_field.hpp"

#include <algorithm>
#include <cmath>
#include <Eigen/Dense>

namespace cloth {

namespace {

enum class DampingLaw { none, projected, report };

// Adds the spring and damping forces of springs [first, last) to F. For a spring (p, q) with d = x_p - x_q,
// l = |d|, u = d / l: spring K (L0 - l) u; projected damper -D ((v_p - v_q) . u) u; report damper
// -D (v_p - v_q) l. q receives the opposite force.
// [spring_force_loop]
template <DampingLaw law>
void add_spring_forces(const Spring* first, const Spring* last, double K, double D, const double* X, const double* V,
                       double* F) {
  for (const Spring* s = first; s != last; ++s) {
    const int p = 3 * s->p;
    const int q = 3 * s->q;
    const double d0 = X[p] - X[q], d1 = X[p + 1] - X[q + 1], d2 = X[p + 2] - X[q + 2];
    const double l = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
    if (l <= degenerate_length_fraction * s->rest_length) continue;  // no direction: no force (Chapter 7)
    const double inv_l = 1.0 / l;
    double c = K * (s->rest_length * inv_l - 1.0);  // K (L0 - l) / l: the force is c d
    double f0 = 0, f1 = 0, f2 = 0;
    if constexpr (law == DampingLaw::projected) {
      const double w0 = V[p] - V[q], w1 = V[p + 1] - V[q + 1], w2 = V[p + 2] - V[q + 2];
      c -= D * (w0 * d0 + w1 * d1 + w2 * d2) * inv_l * inv_l;
    } else if constexpr (law == DampingLaw::report) {
      const double Dl = D * l;
      f0 = -Dl * (V[p] - V[q]);
      f1 = -Dl * (V[p + 1] - V[q + 1]);
      f2 = -Dl * (V[p + 2] - V[q + 2]);
    }
    f0 += c * d0;
    f1 += c * d1;
    f2 += c * d2;
    F[p] += f0, F[p + 1] += f1, F[p + 2] += f2;
    F[q] -= f0, F[q + 1] -= f1, F[q + 2] -= f2;
  }
}
// [spring_force_loop]

}  // namespace

ForceField::ForceField(const Scene& scene)
    : scene_(scene),
      X_(scene.rest_positions()),
      V_(Vector::Zero(3 * scene.particle_count())),
      F_(Vector::Zero(3 * scene.particle_count())) {
  // The pattern: a 3x3 block on the diagonal of every free particle and, for every spring joining two free
  // particles, the blocks (p, q) and (q, p). Built once; every later fill writes values in place.
  const int n_free = scene.free_count();
  const auto& springs = scene.springs().springs;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(9 * (static_cast<std::size_t>(n_free) + 2 * springs.size()));
  const auto add_block = [&](int r, int c) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) triplets.emplace_back(3 * r + a, 3 * c + b, 0.0);
  };
  for (int s = 0; s < n_free; ++s) add_block(s, s);
  for (const Spring& s : springs)
    if (s.p < n_free && s.q < n_free) {
      add_block(s.p, s.q);
      add_block(s.q, s.p);
    }
  pattern_.resize(3 * n_free, 3 * n_free);
  pattern_.setFromTriplets(triplets.begin(), triplets.end());
  pattern_.makeCompressed();

  // Rows of a block are consecutive in each of its columns, so a block is found by three column starts.
  const auto entry = [&](int row, int col) {
    const int* rows = pattern_.innerIndexPtr();
    const int* begin = rows + pattern_.outerIndexPtr()[col];
    const int* end = rows + pattern_.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - rows);
  };
  const auto block = [&](int r, int c) {
    std::array<int, 3> start{-1, -1, -1};
    if (r < n_free && c < n_free)
      for (int b = 0; b < 3; ++b) start[static_cast<std::size_t>(b)] = entry(3 * r, 3 * c + b);
    return start;
  };
  spring_blocks_.reserve(springs.size());
  for (const Spring& s : springs)
    spring_blocks_.push_back({{block(s.p, s.p), block(s.q, s.q), block(s.p, s.q), block(s.q, s.p)}});
  diagonal_entry_.resize(static_cast<std::size_t>(3 * n_free));
  for (int k = 0; k < 3 * n_free; ++k) diagonal_entry_[static_cast<std::size_t>(k)] = entry(k, k);
  diagonal_blocks_.reserve(static_cast<std::size_t>(n_free));
  for (int s = 0; s < n_free; ++s) diagonal_blocks_.push_back(block(s, s));
}

void ForceField::scatter_state(const ConstVectorRef& x, const ConstVectorRef& v) {
  const int n = dof_count();
  X_.head(n) = x;
  if (scene_.has_damping()) V_.head(n) = v;
}

void ForceField::forces(const ConstVectorRef& x, const ConstVectorRef& v, VectorRef f) {
  scatter_state(x, v);
  F_.setZero();
  const auto& set = scene_.springs();
  const Spring* springs = set.springs.data();
  for (SpringFamily family : all_spring_families) {
    const SpringRange r = set.family[static_cast<int>(family)];
    if (r.size() == 0) continue;
    const double K = scene_.stiffness(family);
    const double D = scene_.damping(family);
    const Spring* first = springs + r.begin;
    const Spring* last = springs + r.end;
    if (D == 0.0)
      add_spring_forces<DampingLaw::none>(first, last, K, D, X_.data(), V_.data(), F_.data());
    else if (scene_.params().damping_model == DampingModel::projected)
      add_spring_forces<DampingLaw::projected>(first, last, K, D, X_.data(), V_.data(), F_.data());
    else
      add_spring_forces<DampingLaw::report>(first, last, K, D, X_.data(), V_.data(), F_.data());
  }
  f = F_.head(dof_count());
  if (scene_.has_gravity()) {
    const double weight = scene_.params().mass * scene_.params().gravity;
    for (int s = 0; s < scene_.free_count(); ++s) f[3 * s + 2] -= weight;
  }
}

void ForceField::acceleration(const ConstVectorRef& x, const ConstVectorRef& v, VectorRef a) {
  forces(x, v, a);
  a *= 1.0 / scene_.params().mass;
}

Energy ForceField::energy(const ConstVectorRef& x, const ConstVectorRef& v) {
  X_.head(dof_count()) = x;
  const double m = scene_.params().mass;
  Energy e;
  e.kinetic = 0.5 * m * v.squaredNorm();
  for (int s = 0; s < scene_.particle_count(); ++s) e.gravity += X_[3 * s + 2];
  e.gravity *= m * scene_.params().gravity;
  const auto& set = scene_.springs();
  for (SpringFamily family : all_spring_families) {
    const SpringRange r = set.family[static_cast<int>(family)];
    double sum = 0;
    for (int k = r.begin; k < r.end; ++k) {
      const Spring& s = set.springs[static_cast<std::size_t>(k)];
      const double stretch = (X_.segment<3>(3 * s.p) - X_.segment<3>(3 * s.q)).norm() - s.rest_length;
      sum += stretch * stretch;
    }
    e.spring += 0.5 * scene_.stiffness(family) * sum;
  }
  return e;
}

// Calls add(blocks, Bx, Bv) for every spring, with Bx = df_p/dx_p and Bv = df_p/dv_p. Every force of a spring
// depends on x_p - x_q and v_p - v_q only, so its four blocks are +B at (p,p), (q,q) and -B at (p,q), (q,p).
// Expects scatter_state() to have run.
template <class AddBlocks>
void ForceField::for_each_spring_block(StiffnessTreatment treatment, AddBlocks&& add) {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  const auto& set = scene_.springs();
  const DampingModel model = scene_.params().damping_model;
  const bool exact = treatment == StiffnessTreatment::exact;
  const bool definite = treatment == StiffnessTreatment::definite;
  const Matrix3d I = Matrix3d::Identity();
  for (SpringFamily family : all_spring_families) {
    const SpringRange r = set.family[static_cast<int>(family)];
    const double K = scene_.stiffness(family);
    const double D = scene_.damping(family);
    for (int k = r.begin; k < r.end; ++k) {
      const Spring& s = set.springs[static_cast<std::size_t>(k)];
      const Vector3d d = X_.segment<3>(3 * s.p) - X_.segment<3>(3 * s.q);
      const double l = d.norm();
      if (l <= degenerate_length_fraction * s.rest_length) continue;
      const Vector3d u = d / l;
      const Matrix3d uu = u * u.transpose();
      // Spring: df_p/dx_p = -K [u u^T + (1 - L0/l)(I - u u^T)]. A compressed spring (l < L0) makes the
      // transverse coefficient negative, so the block is indefinite; Choi & Ko (2002) drop it.
      double transverse = 1.0 - s.rest_length / l;
      if (definite) transverse = std::max(transverse, 0.0);
      Matrix3d Bx = -K * (uu + transverse * (I - uu));
      Matrix3d Bv = Matrix3d::Zero();
      if (D != 0.0) {
        const Vector3d w = V_.segment<3>(3 * s.p) - V_.segment<3>(3 * s.q);
        if (model == DampingModel::projected) {
          // f_p = -D (w.u) u: df/dv = -D u u^T; df/dx = -(D/l) [u w^T P + (w.u) P], P = I - u u^T.
          Bv = -D * uu;
          if (exact) {
            const Matrix3d P = I - uu;
            Bx -= (D / l) * (u * (P * w).transpose() + w.dot(u) * P);
          }
        } else {
          // f_p = -D w l: df/dv = -D l I; df/dx = -D w u^T.
          Bv = -D * l * I;
          if (exact) Bx -= D * w * u.transpose();
        }
      }
      add(spring_blocks_[static_cast<std::size_t>(k)], Bx, Bv);
    }
  }
}

namespace {

// values[block column starts + row] += sign * B, for one 3x3 block; start[0] < 0 means the block is absent.
inline void add_block(double* values, const std::array<int, 3>& start, const Eigen::Matrix3d& B, double sign) {
  if (start[0] < 0) return;
  for (int b = 0; b < 3; ++b) {
    double* column = values + start[static_cast<std::size_t>(b)];
    column[0] += sign * B(0, b);
    column[1] += sign * B(1, b);
    column[2] += sign * B(2, b);
  }
}

}  // namespace

void ForceField::jacobians(const ConstVectorRef& x, const ConstVectorRef& v, SparseMatrix& dfdx, SparseMatrix& dfdv) {
  scatter_state(x, v);
  std::fill_n(dfdx.valuePtr(), dfdx.nonZeros(), 0.0);
  std::fill_n(dfdv.valuePtr(), dfdv.nonZeros(), 0.0);
  double* Jx = dfdx.valuePtr();
  double* Jv = dfdv.valuePtr();
  for_each_spring_block(StiffnessTreatment::exact,
                        [&](const SpringBlocks& blocks, const Eigen::Matrix3d& Bx, const Eigen::Matrix3d& Bv) {
                          const auto& c = blocks.column_start;
                          add_block(Jx, c[0], Bx, 1), add_block(Jx, c[1], Bx, 1);
                          add_block(Jx, c[2], Bx, -1), add_block(Jx, c[3], Bx, -1);
                          add_block(Jv, c[0], Bv, 1), add_block(Jv, c[1], Bv, 1);
                          add_block(Jv, c[2], Bv, -1), add_block(Jv, c[3], Bv, -1);
                        });
}

namespace {

// values[block] += sign (alpha u u^T + beta I), or = when `assign`: the one block shape of the lean refill
// (symmetric, 6 numbers).
template <bool assign>
inline void put_rank_one_plus_identity(double* values, const std::array<int, 3>& start, double alpha, double beta,
                                       const double* u, double sign) {
  if (start[0] < 0) return;
  const double a = sign * alpha, b = sign * beta;
  const double u00 = a * u[0] * u[0], u11 = a * u[1] * u[1], u22 = a * u[2] * u[2];
  const double u01 = a * u[0] * u[1], u02 = a * u[0] * u[2], u12 = a * u[1] * u[2];
  double* c0 = values + start[0];
  double* c1 = values + start[1];
  double* c2 = values + start[2];
  if constexpr (assign) {
    c0[0] = u00 + b, c0[1] = u01, c0[2] = u02;
    c1[0] = u01, c1[1] = u11 + b, c1[2] = u12;
    c2[0] = u02, c2[1] = u12, c2[2] = u22 + b;
  } else {
    c0[0] += u00 + b, c0[1] += u01, c0[2] += u02;
    c1[0] += u01, c1[1] += u11 + b, c1[2] += u12;
    c2[0] += u02, c2[1] += u12, c2[2] += u22 + b;
  }
}

}  // namespace

// [lean_refill]
// The Newton matrix when every spring block has the shape alpha u u^T + beta I: no damping, or projected damping
// without its d/dx (the symmetric and definite treatments). With t = 1 - L0/l (clamped at 0 for definite),
//   -h^2 df_p/dx_p = h^2 K [u u^T + t (I - u u^T)],   -h df_p/dv_p = h D u u^T,
// so alpha = h^2 K (1 - t) + h D and beta = h^2 K t: six numbers per block instead of two 3x3 matrix products.
void ForceField::refill_symmetric(double h, bool definite, double* values) {
  const auto& set = scene_.springs();
  const double* X = X_.data();
  for (SpringFamily family : all_spring_families) {
    const SpringRange r = set.family[static_cast<int>(family)];
    const double h2K = h * h * scene_.stiffness(family);
    const double hD = h * scene_.damping(family);
    for (int k = r.begin; k < r.end; ++k) {
      const Spring& s = set.springs[static_cast<std::size_t>(k)];
      const int p = 3 * s.p, q = 3 * s.q;
      const double d[3] = {X[p] - X[q], X[p + 1] - X[q + 1], X[p + 2] - X[q + 2]};
      const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      // A degenerate spring contributes nothing, but still writes its (zero) off-diagonal blocks.
      const bool degenerate = l <= degenerate_length_fraction * s.rest_length;
      const double inv_l = degenerate ? 0.0 : 1.0 / l;
      const double u[3] = {d[0] * inv_l, d[1] * inv_l, d[2] * inv_l};
      double t = 1.0 - s.rest_length * inv_l;
      if (definite) t = std::max(t, 0.0);
      const double alpha = degenerate ? 0.0 : h2K * (1.0 - t) + hD, beta = degenerate ? 0.0 : h2K * t;
      const auto& c = spring_blocks_[static_cast<std::size_t>(k)].column_start;
      // Diagonal blocks collect every spring of their particle; an off-diagonal block belongs to one spring
      // alone, so it is assigned, and only the diagonal blocks had to be cleared.
      put_rank_one_plus_identity<false>(values, c[0], alpha, beta, u, 1.0);
      put_rank_one_plus_identity<false>(values, c[1], alpha, beta, u, 1.0);
      put_rank_one_plus_identity<true>(values, c[2], alpha, beta, u, -1.0);
      put_rank_one_plus_identity<true>(values, c[3], alpha, beta, u, -1.0);
    }
  }
}
// [lean_refill]

void ForceField::newton_matrix(const ConstVectorRef& x, const ConstVectorRef& v, double h,
                               StiffnessTreatment treatment, SparseMatrix& A) {
  scatter_state(x, v);
  double* values = A.valuePtr();
  const double m = scene_.params().mass;
  // Without damping, exact and symmetric are the same matrix; projected damping is symmetric once its d/dx goes.
  const bool lean = !scene_.has_damping() ||
                    (scene_.params().damping_model == DampingModel::projected && treatment != StiffnessTreatment::exact);
  if (lean) {
    // Every off-diagonal block is assigned by its spring, so only the diagonal blocks are cleared.
    for (const auto& start : diagonal_blocks_)
      for (int b : start) std::fill_n(values + b, 3, 0.0);
    for (int k : diagonal_entry_) values[k] = m;
    refill_symmetric(h, treatment == StiffnessTreatment::definite, values);
    return;
  }
  std::fill_n(values, A.nonZeros(), 0.0);
  for (int k : diagonal_entry_) values[k] = m;
  for_each_spring_block(treatment, [&](const SpringBlocks& blocks, const Eigen::Matrix3d& Bx, const Eigen::Matrix3d& Bv) {
    // A = M - h df/dv - h^2 df/dx, block by block.
    const Eigen::Matrix3d C = -h * Bv - (h * h) * Bx;
    const auto& c = blocks.column_start;
    add_block(values, c[0], C, 1), add_block(values, c[1], C, 1);
    add_block(values, c[2], C, -1), add_block(values, c[3], C, -1);
  });
}

}  // namespace cloth
