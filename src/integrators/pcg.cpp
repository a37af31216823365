// Block-Jacobi preconditioned conjugate gradients, written out so that a solve touches only preallocated memory.
#include "integrators/pcg.hpp"

#include <cmath>

namespace cloth {

BlockJacobiPCG::BlockJacobiPCG(int n)
    : inverse_blocks_(3 * static_cast<std::size_t>(n)), r_(n), z_(n), p_(n), q_(n) {}

bool BlockJacobiPCG::compute(const SparseMatrix& A) {
  const int* outer = A.outerIndexPtr();
  const int* rows = A.innerIndexPtr();
  const double* values = A.valuePtr();
  const int particles = static_cast<int>(A.cols()) / 3;
  for (int s = 0; s < particles; ++s) {
    // The block's three columns, rows 3s..3s+2 (consecutive in each column, see ForceField's pattern).
    double B[3][3];
    for (int b = 0; b < 3; ++b) {
      const int col = 3 * s + b;
      int k = outer[col];
      while (rows[k] != 3 * s) ++k;
      for (int a = 0; a < 3; ++a) B[a][b] = values[k + a];
    }
    // Inverse by the adjugate; a symmetric positive definite block has positive leading minors.
    const double c00 = B[1][1] * B[2][2] - B[1][2] * B[2][1];
    const double c01 = B[1][2] * B[2][0] - B[1][0] * B[2][2];
    const double c02 = B[1][0] * B[2][1] - B[1][1] * B[2][0];
    const double det = B[0][0] * c00 + B[0][1] * c01 + B[0][2] * c02;
    if (!(B[0][0] > 0 && det > 0)) return false;
    const double inv = 1.0 / det;
    double* Z = &inverse_blocks_[9 * static_cast<std::size_t>(s)];
    Z[0] = c00 * inv, Z[3] = c01 * inv, Z[6] = c02 * inv;
    Z[1] = (B[0][2] * B[2][1] - B[0][1] * B[2][2]) * inv;
    Z[4] = (B[0][0] * B[2][2] - B[0][2] * B[2][0]) * inv;
    Z[7] = (B[0][1] * B[2][0] - B[0][0] * B[2][1]) * inv;
    Z[2] = (B[0][1] * B[1][2] - B[0][2] * B[1][1]) * inv;
    Z[5] = (B[0][2] * B[1][0] - B[0][0] * B[1][2]) * inv;
    Z[8] = (B[0][0] * B[1][1] - B[0][1] * B[1][0]) * inv;
  }
  return true;
}

void BlockJacobiPCG::precondition(const Vector& r, Vector& z) const {
  const Eigen::Index particles = r.size() / 3;
  for (Eigen::Index s = 0; s < particles; ++s) {
    const double* Z = &inverse_blocks_[9 * static_cast<std::size_t>(s)];
    const double r0 = r[3 * s], r1 = r[3 * s + 1], r2 = r[3 * s + 2];
    z[3 * s] = Z[0] * r0 + Z[1] * r1 + Z[2] * r2;
    z[3 * s + 1] = Z[3] * r0 + Z[4] * r1 + Z[5] * r2;
    z[3 * s + 2] = Z[6] * r0 + Z[7] * r1 + Z[8] * r2;
  }
}

namespace {
// y = A x for the full (both triangles) column-major storage of a symmetric A: column j of A is row j, so y_j is
// the dot product of column j with x, a gather with no scattered writes.
void multiply(const SparseMatrix& A, const Vector& x, Vector& y) {
  const int* outer = A.outerIndexPtr();
  const int* rows = A.innerIndexPtr();
  const double* values = A.valuePtr();
  const double* X = x.data();
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    double sum = 0;
    for (int k = outer[j]; k < outer[j + 1]; ++k) sum += values[k] * X[rows[k]];
    y[j] = sum;
  }
}
}  // namespace

// [pcg]
bool BlockJacobiPCG::solve(const SparseMatrix& A, const Vector& b, Vector& x, double tol, int max_iterations) {
  iterations_ = 0;
  const double b_norm2 = b.squaredNorm();
  if (b_norm2 == 0.0) {
    x.setZero();
    return true;
  }
  const double threshold2 = tol * tol * b_norm2;
  multiply(A, x, q_);
  r_ = b - q_;  // the warm start's residual
  double r_norm2 = r_.squaredNorm();
  if (r_norm2 <= threshold2) return true;
  precondition(r_, z_);
  p_ = z_;
  double rz = r_.dot(z_);
  while (iterations_ < max_iterations) {
    multiply(A, p_, q_);
    const double pq = p_.dot(q_);
    if (!(pq > 0)) return false;  // A is not positive definite along p
    const double alpha = rz / pq;
    x.noalias() += alpha * p_;
    r_.noalias() -= alpha * q_;
    ++iterations_;
    r_norm2 = r_.squaredNorm();
    if (r_norm2 <= threshold2) return true;
    precondition(r_, z_);
    const double rz_next = r_.dot(z_);
    p_ = z_ + (rz_next / rz) * p_;
    rz = rz_next;
  }
  return false;
}
// [pcg]

}  // namespace cloth
