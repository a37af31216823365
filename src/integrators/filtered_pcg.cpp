// The filtered (modified) conjugate gradients of Baraff & Witkin 1998 and the per-particle projectors it filters by.
#include "integrators/filtered_pcg.hpp"

#include <Eigen/Cholesky>

namespace cloth {

ConstraintFilter::ConstraintFilter(int particles)
    : S_(static_cast<std::size_t>(particles), Eigen::Matrix3d::Identity()) {}

void ConstraintFilter::clear() {
  for (Eigen::Matrix3d& S : S_) S.setIdentity();
}

void ConstraintFilter::constrain(int s, const Eigen::Vector3d& n) {
  Eigen::Matrix3d& S = S_[static_cast<std::size_t>(s)];
  const Eigen::Vector3d free_part = S * n;  // Gram-Schmidt against the directions already constrained
  const double length = free_part.norm();
  if (!(length > 1e-12 * n.norm())) return;
  const Eigen::Vector3d u = free_part / length;
  S -= u * u.transpose();
}

void ConstraintFilter::fix(int s) { S_[static_cast<std::size_t>(s)].setZero(); }

void ConstraintFilter::apply(Eigen::Ref<Vector> a) const {
  for (std::size_t s = 0; s < S_.size(); ++s) {
    const auto k = static_cast<Eigen::Index>(3 * s);
    const Eigen::Vector3d a_s = a.segment<3>(k);
    a.segment<3>(k) = S_[s] * a_s;
  }
}

void ConstraintFilter::apply_complement(Eigen::Ref<Vector> a) const {
  for (std::size_t s = 0; s < S_.size(); ++s) {
    const auto k = static_cast<Eigen::Index>(3 * s);
    const Eigen::Vector3d a_s = a.segment<3>(k);
    a.segment<3>(k) = a_s - S_[s] * a_s;
  }
}

FilteredPCG::FilteredPCG(int n)
    : inverse_blocks_(static_cast<std::size_t>(n / 3)), r_(n), s_(n), c_(n), q_(n), fixed_(n) {}

bool FilteredPCG::compute(const SparseMatrix& A) {
  for (std::size_t s = 0; s < inverse_blocks_.size(); ++s) {
    const auto k = static_cast<Eigen::Index>(3 * s);
    Eigen::Matrix3d B;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) B(a, b) = A.coeff(k + a, k + b);
    Eigen::LLT<Eigen::Matrix3d> llt(B);
    if (llt.info() != Eigen::Success) return false;
    inverse_blocks_[s] = llt.solve(Eigen::Matrix3d::Identity());
  }
  return true;
}

void FilteredPCG::precondition(const Vector& r, Vector& s) const {
  for (std::size_t p = 0; p < inverse_blocks_.size(); ++p) {
    const auto k = static_cast<Eigen::Index>(3 * p);
    s.segment<3>(k).noalias() = inverse_blocks_[p] * r.segment<3>(k);
  }
}

// [filtered_pcg]
bool FilteredPCG::solve(const SparseMatrix& A, const Vector& b, const ConstraintFilter& filter, const Vector& z,
                        Vector& dv, double tol, int max_iterations) {
  iterations_ = 0;
  // dv = S dv + (I - S) z: the prescribed components set once; every later update is filtered, so they stay.
  fixed_ = z;
  filter.apply_complement(fixed_);
  filter.apply(dv);
  dv += fixed_;
  // The residual of the free equations only: r = S (b - A dv). The constrained rows of A dv = b are not
  // equations at all (their components are given), so they are filtered out of every residual.
  // The tolerance is relative to the free residual of the cold start dv = (I - S) z, whatever the warm start.
  q_.noalias() = A * fixed_;
  r_ = b - q_;
  filter.apply(r_);
  const double threshold2 = tol * tol * r_.squaredNorm();
  q_.noalias() = A * dv;
  r_ = b - q_;
  filter.apply(r_);
  if (r_.squaredNorm() <= threshold2) return true;
  precondition(r_, s_);
  c_ = s_;
  filter.apply(c_);  // the search direction lies in the free subspace
  double delta = r_.dot(c_);
  while (iterations_ < max_iterations) {
    q_.noalias() = A * c_;
    filter.apply(q_);  // q = S A c: the Krylov space is that of S A S, symmetric positive definite on S's range
    const double cq = c_.dot(q_);
    if (!(cq > 0)) return false;
    const double alpha = delta / cq;
    dv.noalias() += alpha * c_;
    r_.noalias() -= alpha * q_;
    ++iterations_;
    if (r_.squaredNorm() <= threshold2) return true;
    precondition(r_, s_);
    const double delta_next = r_.dot(s_);
    c_ = s_ + (delta_next / delta) * c_;
    filter.apply(c_);
    delta = delta_next;
  }
  return false;
}
// [filtered_pcg]

}  // namespace cloth
