// The cloth's matrices as Spectra sees them: operators that only multiply a vector (the "perform_op" concept of
// Spectra's Lanczos and Arnoldi solvers), so that no matrix beyond the sparse Jacobians is ever formed.
#pragma once

#include "model/force_field.hpp"

namespace cloth {

/// y = s A x for a sparse A: -M^{-1} df/dx or -M^{-1} df/dv with s = -1/m (equal particle masses).
class ScaledSparseProduct {
 public:
  using Scalar = double;
  ScaledSparseProduct(const SparseMatrix& A, double s) : A_(A), s_(s) {}
  [[nodiscard]] Eigen::Index rows() const { return A_.rows(); }
  [[nodiscard]] Eigen::Index cols() const { return A_.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<Vector> y(y_out, A_.rows());
    y.noalias() = A_ * Eigen::Map<const Vector>(x_in, A_.cols());
    y *= s_;
  }

 private:
  const SparseMatrix& A_;
  double s_;
};

/// y = J x for the first-order system J = [[0, I], [M^{-1} df/dx, M^{-1} df/dv]] of size 2n, from the two
/// sparse n x n Jacobians: J (a, b) = (b, (df/dx a + df/dv b) / m).
class FirstOrderSystemProduct {
 public:
  using Scalar = double;
  FirstOrderSystemProduct(const SparseMatrix& dfdx, const SparseMatrix& dfdv, double mass)
      : dfdx_(dfdx), dfdv_(dfdv), inverse_mass_(1.0 / mass), n_(dfdx.rows()) {}
  [[nodiscard]] Eigen::Index rows() const { return 2 * n_; }
  [[nodiscard]] Eigen::Index cols() const { return 2 * n_; }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const Vector> a(x_in, n_), b(x_in + n_, n_);
    Eigen::Map<Vector> y_x(y_out, n_), y_v(y_out + n_, n_);
    y_x = b;
    y_v.noalias() = dfdx_ * a;
    y_v.noalias() += dfdv_ * b;
    y_v *= inverse_mass_;
  }

 private:
  const SparseMatrix& dfdx_;
  const SparseMatrix& dfdv_;
  double inverse_mass_;
  Eigen::Index n_;
};

}  // namespace cloth
