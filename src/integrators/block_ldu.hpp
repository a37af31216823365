// A sparse direct solver made for the cloth's Newton matrix (Chapter 6): it factors the 396-particle graph, not
// the 1188-row matrix, so every entry it touches is a particle's dense 3x3 block. A = L D L^T for a symmetric
// matrix, A = L D U for the exact, non-symmetric Jacobian of a damped cloth (whose pattern is still symmetric).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "model/force_field.hpp"

namespace cloth {

/// A = P^T L D U P on 3x3 blocks: L unit lower and U unit upper block-triangular, D block diagonal, P a
/// fill-reducing ordering of the particles (approximate minimum degree on the particle graph; Amestoy, Davis &
/// Duff 1996). Symmetric mode has U = L^T and does half the work. There is no pivoting: each pivot block D_k is
/// inverted whole (by cofactors), in the order the fill-reducing ordering chose. For a symmetric positive
/// definite A (the `definite` treatment) that is as stable as Cholesky. For an indefinite or non-symmetric A
/// (compressed springs, the damper's d/dx) nothing bounds the growth of the factors, and a solve can lose digits
/// even when A is well conditioned; solve() therefore checks its backward error and refines the solution
/// (Wilkinson 1963; Higham, Accuracy and Stability of Numerical Algorithms, 2002, ch. 12), and reports how far
/// it got. A pivot block that is singular to working precision makes factorize() fail.
///
/// The matrix comes in ForceField's storage: column-major, compressed, both triangles, every block full and its
/// three rows consecutive. analyze() looks at the pattern once per scene; factorize() and solve() allocate nothing.
class BlockLDU {
 public:
  enum class Symmetry { symmetric, general };

  /// The ordering and the symbolic factorization (the pattern of L), for matrices with A's pattern.
  void analyze(const SparseMatrix& A, Symmetry symmetry);

  /// The numeric factorization of A (same pattern as in analyze()). Returns false when a pivot block D_k is
  /// singular to working precision or not finite; solve() then refuses until a factorization succeeds.
  bool factorize(const SparseMatrix& A);

  /// x = A^{-1} b by the factorization of A, then up to `max_refinements` steps of iterative refinement,
  /// x += (LDU)^{-1} (b - A x), while the normwise backward error |b - A x|_inf / (|A|_inf |x|_inf + |b|_inf)
  /// is above `target` and still falling. Returns that backward error: the caller decides what is good enough.
  /// A must be the matrix last factorized; b may be x.
  double solve(const SparseMatrix& A, const Vector& b, Vector& x, double target = 1e-14, int max_refinements = 6);

  /// Whether the symmetric A last factorized is positive definite. A = P^T L D L^T P is congruent to D, so by
  /// Sylvester's law of inertia it is exactly when every pivot block D_k is: when the three leading principal
  /// minors of each are positive. A few flops per particle, beside the factorization's hundreds.
  [[nodiscard]] bool positive_definite() const;
  /// Number of 3x3 blocks stored in L strictly below the diagonal (the fill the ordering leaves).
  [[nodiscard]] long factor_blocks() const { return static_cast<long>(row_of_entry_.size()); }
  /// Multiply-adds of one numeric factorization, counted from the symbolic pattern.
  [[nodiscard]] double factorization_flops() const;

 private:
  using Block = Eigen::Matrix3d;

  Symmetry symmetry_ = Symmetry::symmetric;
  int n_ = 0;               // particles (block columns)
  std::vector<int> order_;  // order_[k]: the particle eliminated k-th
  // L's strict lower part by block columns, rows ascending (compressed column storage of blocks).
  std::vector<int> column_start_, row_of_entry_;
  // The same pattern by rows: for row k, the columns j < k with L(k, j) != 0 and where that block is stored.
  std::vector<int> row_start_, column_of_row_entry_, entry_of_row_entry_;
  // Where A's blocks go: for block column k, the blocks A(order[t], order[k]) with t >= k, by the target t and
  // the value indices of the block's three columns in A (and of its transpose A(order[k], order[t])).
  std::vector<int> gather_start_, gather_target_;
  std::vector<std::array<int, 3>> gather_lower_, gather_upper_;

  // The blocks of L and U^T and the work blocks carry a fourth row of zeros, so that each of their columns is
  // two whole SIMD registers of two doubles: the 3x3 updates then vectorize.
  using PaddedBlock = Eigen::Matrix<double, 4, 3>;
  std::vector<PaddedBlock> L_, Ut_;        // L(i, k) and U(k, i)^T, in the entries of L's pattern
  std::vector<Block> D_, D_inverse_;       // the pivot blocks D_k and their inverses
  std::vector<PaddedBlock> column_, row_;  // dense work column of L and row of U (as transposes), one per row
  std::vector<Eigen::Vector3d> y_;    // the solve's permuted work vector
  Vector b_, r_, dx_;                 // right-hand side, residual and correction of the refinement
  double norm_A_ = 0;                 // |A|_inf of the matrix last factorized, for the backward error
  bool factored_ = false;
  Eigen::Index rows_ = 0, nonzeros_ = 0;  // the pattern analyze() saw, to catch a matrix of another one

  // x = (P^T L D U P)^{-1} b: the two triangular solves and the block-diagonal one.
  void substitute(const Vector& b, Vector& x);
};

}  // namespace cloth
