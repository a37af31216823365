// Conjugate gradients with constraints enforced by filtering (Baraff & Witkin 1998, section 5.3, the "modified
// PCG"): each particle's unknown is confined to a subspace, its other components held at prescribed values, so
// that implicit Euler can keep a particle in contact from moving into an obstacle within the linear solve itself.
#pragma once

#include "model/force_field.hpp"

#include <Eigen/Core>
#include <vector>

namespace cloth {

/// The filter S = diag(S_1, ..., S_n): S_i is the orthogonal projector onto the directions particle i is free to
/// move in: I when it is free, I - n n^T when one direction n is constrained (a contact), I - n n^T - m m^T for two
/// orthogonal ones, 0 when all three are. Applying S to a vector removes its constrained components.
class ConstraintFilter {
 public:
  explicit ConstraintFilter(int particles);

  /// Every particle free: S = I.
  void clear();
  /// Constrains particle s along n (any non-zero vector): S_s becomes S_s - u u^T with u the unit vector of
  /// S_s n, so that S_s stays a projector when a second or third direction is added; nothing changes when n is
  /// already constrained.
  void constrain(int s, const Eigen::Vector3d& n);
  /// Constrains all three directions of particle s: S_s = 0.
  void fix(int s);

  /// a <- S a.
  void apply(Eigen::Ref<Vector> a) const;
  /// a <- (I - S) a: the constrained components alone.
  void apply_complement(Eigen::Ref<Vector> a) const;

  [[nodiscard]] const Eigen::Matrix3d& block(int s) const { return S_[static_cast<std::size_t>(s)]; }

 private:
  std::vector<Eigen::Matrix3d> S_;
};

/// Solves A dv = b on the free subspace with the constrained components of dv prescribed:
///   S (A dv - b) = 0,  (I - S) dv = (I - S) z,
/// for A symmetric positive definite (full storage, both triangles) and block-Jacobi preconditioned. Every
/// search direction is filtered, so each iterate keeps the prescribed components (I - S) z exactly. Allocates
/// nothing after construction.
class FilteredPCG {
 public:
  explicit FilteredPCG(int n);

  /// Inverts A's 3x3 diagonal blocks; false when one is not positive definite.
  bool compute(const SparseMatrix& A);

  /// Starts from dv = S dv + (I - S) z (the caller's free components, a warm start, and the prescribed ones) and
  /// iterates until |S (b - A dv)|_2 <= tol |S (b - A (I - S) z)|_2 (the free residual of the cold start) or
  /// max_iterations. Returns whether it converged.
  bool solve(const SparseMatrix& A, const Vector& b, const ConstraintFilter& filter, const Vector& z, Vector& dv,
             double tol, int max_iterations);

  [[nodiscard]] int iterations() const { return iterations_; }

 private:
  void precondition(const Vector& r, Vector& s) const;

  std::vector<Eigen::Matrix3d> inverse_blocks_;
  Vector r_, s_, c_, q_, fixed_;
  int iterations_ = 0;
};

}  // namespace cloth
