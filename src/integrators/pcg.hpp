// Preconditioned conjugate gradients for the Newton systems of implicit Euler (Chapter 6): block-Jacobi
// preconditioned (the inverse of each particle's 3x3 diagonal block), warm-startable, and allocation-free after
// construction, unlike Eigen's ConjugateGradient, which allocates its work vectors on every solve.
#pragma once

#include "model/force_field.hpp"

#include <vector>

namespace cloth {

/// Solves A x = b for a symmetric positive definite A stored in full (both triangles, column-major), the storage
/// ForceField::newton_matrix fills. CG: Hestenes & Stiefel (1952); Saad, Iterative Methods, Alg. 9.1.
class BlockJacobiPCG {
 public:
  /// Work space for systems of `n` unknowns (n a multiple of 3).
  explicit BlockJacobiPCG(int n);

  /// Inverts the 3x3 diagonal blocks of A, the preconditioner. Returns false when a block is not positive
  /// definite (then A is not either).
  bool compute(const SparseMatrix& A);

  /// Iterates from the x it is given (a warm start; zero it for a cold one) until |b - A x|_2 <= tol |b|_2 or
  /// max_iterations. Returns whether it converged; iterations() tells how many it took.
  bool solve(const SparseMatrix& A, const Vector& b, Vector& x, double tol, int max_iterations);

  [[nodiscard]] int iterations() const { return iterations_; }

 private:
  void precondition(const Vector& r, Vector& z) const;

  std::vector<double> inverse_blocks_;  // 9 per particle, row-major
  Vector r_, z_, p_, q_;
  int iterations_ = 0;
};

}  // namespace cloth
