// The block LDL^T / LDU factorization of block_ldu.hpp: an ordering and an elimination tree on the particle graph
// (analysed once per scene), then a left-looking numeric factorization whose every operation is a 3x3 product.
#include "integrators/block_ldu.hpp"

#include <Eigen/LU>
#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cmath>
#include <limits>

namespace cloth {

void BlockLDU::analyze(const SparseMatrix& A, Symmetry symmetry) {
  eigen_assert(A.isCompressed() && A.rows() == A.cols() && A.cols() % 3 == 0);
  symmetry_ = symmetry;
  factored_ = false;
  rows_ = A.rows();
  nonzeros_ = A.nonZeros();
  n_ = static_cast<int>(A.cols() / 3);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  // The particles each particle is coupled to: the block rows of its first scalar column, one per three rows.
  const auto for_each_block_row = [&](int c, auto&& visit) {
    for (int e = outer[3 * c]; e < outer[3 * c + 1]; e += 3) visit(inner[e] / 3);
  };

  // The fill-reducing ordering, computed on the particle graph (n_ nodes instead of 3 n_ rows).
  {
    std::vector<Eigen::Triplet<double>> coupling;
    for (int c = 0; c < n_; ++c) for_each_block_row(c, [&](int r) { coupling.emplace_back(r, c, 1.0); });
    SparseMatrix graph(n_, n_);
    graph.setFromTriplets(coupling.begin(), coupling.end());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation;
    Eigen::AMDOrdering<int>()(graph, permutation);
    order_.assign(permutation.indices().data(), permutation.indices().data() + n_);
  }
  std::vector<int> position(n_);
  for (int k = 0; k < n_; ++k) position[order_[k]] = k;

  // The pattern of L, row by row (Liu 1986; Davis, Direct Methods for Sparse Linear Systems, 2006, 4.1): row k
  // of L holds every column reached by climbing the elimination tree from the columns j < k that A couples to k,
  // up to the first one already visited for this row. The tree is built on the way: a column without a parent
  // yet gets k.
  std::vector<int> parent(n_, -1), visited(n_, -1);
  std::vector<std::vector<int>> rows_of_column(n_);
  std::vector<std::pair<int, int>> row_entries;  // (column j, index of row k in column j), row after row
  row_start_.assign(1, 0);
  for (int k = 0; k < n_; ++k) {
    visited[k] = k;
    for_each_block_row(order_[k], [&](int r) {
      if (position[r] > k) return;  // the upper triangle: row k of L needs only columns j < k
      for (int j = position[r]; visited[j] != k; j = parent[j]) {
        auto& rows = rows_of_column[j];
        row_entries.emplace_back(j, static_cast<int>(rows.size()));
        rows.push_back(k);
        visited[j] = k;
        if (parent[j] == -1) parent[j] = k;
      }
    });
    row_start_.push_back(static_cast<int>(row_entries.size()));
  }
  column_start_.assign(1, 0);
  row_of_entry_.clear();
  for (const auto& rows : rows_of_column) {
    row_of_entry_.insert(row_of_entry_.end(), rows.begin(), rows.end());
    column_start_.push_back(static_cast<int>(row_of_entry_.size()));
  }
  column_of_row_entry_.clear();
  entry_of_row_entry_.clear();
  for (const auto& [j, index] : row_entries) {
    column_of_row_entry_.push_back(j);
    entry_of_row_entry_.push_back(column_start_[j] + index);
  }

  // Where each block of A lands: block (r, c) has its three rows consecutive in each of its three columns.
  const auto block_start = [&](int r, int c) {
    std::array<int, 3> start{};
    for (int b = 0; b < 3; ++b) {
      const int* begin = inner + outer[3 * c + b];
      const int* end = inner + outer[3 * c + b + 1];
      start[b] = static_cast<int>(std::lower_bound(begin, end, 3 * r) - inner);
    }
    return start;
  };
  gather_start_.assign(1, 0);
  gather_target_.clear();
  gather_lower_.clear();
  gather_upper_.clear();
  for (int k = 0; k < n_; ++k) {
    const int c = order_[k];
    for_each_block_row(c, [&](int r) {
      const int t = position[r];
      if (t < k) return;
      gather_target_.push_back(t);
      gather_lower_.push_back(block_start(r, c));
      if (symmetry == Symmetry::general) gather_upper_.push_back(block_start(c, r));
    });
    gather_start_.push_back(static_cast<int>(gather_target_.size()));
  }

  const auto blocks = row_of_entry_.size();
  L_.assign(blocks, PaddedBlock::Zero());
  Ut_.assign(symmetry == Symmetry::general ? blocks : 0, PaddedBlock::Zero());
  D_.assign(n_, Block::Zero());
  D_inverse_.assign(n_, Block::Zero());
  column_.assign(n_, PaddedBlock::Zero());
  row_.assign(symmetry == Symmetry::general ? n_ : 0, PaddedBlock::Zero());
  y_.assign(n_, Eigen::Vector3d::Zero());
  b_.resize(rows_), r_.resize(rows_), dx_.resize(rows_);
}

double BlockLDU::factorization_flops() const {
  // Per row entry L(k, j) reaching m blocks of column j from row k down: one 3x3 product for the multiplier and
  // m updates (general: two multipliers, m updates of the column and m - 1 of the row); per block of L, one
  // product to scale it by D_k^{-1} (general: two).
  const bool general = symmetry_ == Symmetry::general;
  double products = 0;
  for (int k = 0; k < n_; ++k)
    for (int r = row_start_[k]; r < row_start_[k + 1]; ++r) {
      const int m = column_start_[column_of_row_entry_[r] + 1] - entry_of_row_entry_[r];
      products += general ? 2 * m + 1 : m + 1;
    }
  products += static_cast<double>(row_of_entry_.size()) * (general ? 2 : 1);
  return 27 * products;
}

// [block_ldu_factorize]
bool BlockLDU::positive_definite() const {
  return factored_ && std::all_of(D_.begin(), D_.end(), [](const Block& D) {
           return D(0, 0) > 0 && D(0, 0) * D(1, 1) - D(1, 0) * D(0, 1) > 0 && D.determinant() > 0;
         });
}

bool BlockLDU::factorize(const SparseMatrix& A) {
  eigen_assert(A.rows() == rows_ && A.nonZeros() == nonzeros_ && A.isCompressed());
  factored_ = false;
  const double* a = A.valuePtr();
  const bool general = symmetry_ == Symmetry::general;
  for (int k = 0; k < n_; ++k) {
    // Block column k of A (rows >= k, in elimination order) into the work column; its transpose, block row k
    // of A, into the work row.
    for (int g = gather_start_[k]; g < gather_start_[k + 1]; ++g) {
      const auto t = gather_target_[g];
      const auto& lower = gather_lower_[g];
      for (int b = 0; b < 3; ++b)
        for (int i = 0; i < 3; ++i) column_[t](i, b) = a[lower[b] + i];
      if (!general) continue;  // the transposes are gathered (and their places recorded) in general mode only
      const auto& upper = gather_upper_[g];
      for (int b = 0; b < 3; ++b)
        for (int i = 0; i < 3; ++i) row_[t](b, i) = a[upper[b] + i];
    }
    // Left-looking: subtract L(i, j) D_j U(j, k) for every earlier column j that reaches row k; column j's
    // blocks from row k down are contiguous, so each update is a run of 3x3 products.
    for (int r = row_start_[k]; r < row_start_[k + 1]; ++r) {
      const auto j = column_of_row_entry_[r];
      const int first = entry_of_row_entry_[r];  // L(k, j)
      const int end = column_start_[j + 1];
      const auto L_kj = L_[first].topRows<3>();
      const Block DU = D_[j] * (general ? Ut_[first].topRows<3>() : L_kj).transpose();
      for (int e = first; e < end; ++e) column_[row_of_entry_[e]].noalias() -= L_[e] * DU;
      if (general) {
        const Block LDt = (L_kj * D_[j]).transpose();
        for (int e = first + 1; e < end; ++e) row_[row_of_entry_[e]].noalias() -= Ut_[e] * LDt;
      }
    }
    // The pivot block D_k, inverted whole. |det| against the product of its column norms (Hadamard's bound)
    // is a scale-free test: it is 1 for orthogonal columns and 0 for dependent ones.
    D_[k] = column_[k].topRows<3>();
    column_[k].setZero();
    const double det = D_[k].determinant();
    const double bound = D_[k].col(0).norm() * D_[k].col(1).norm() * D_[k].col(2).norm();
    // Stale work blocks a failure leaves behind need no cleaning: a row's first block in L (its smallest
    // column) is always an entry of A (Liu 1986), so the next factorization assigns each work block before it
    // updates it.
    if (!std::isfinite(det) || !(std::abs(det) > 64 * std::numeric_limits<double>::epsilon() * bound)) return false;
    D_inverse_[k] = D_[k].inverse();
    // Column k of L is the work column times D_k^{-1}; row k of U is D_k^{-1} times the work row.
    for (int e = column_start_[k]; e < column_start_[k + 1]; ++e) {
      const auto i = row_of_entry_[e];
      L_[e].noalias() = column_[i] * D_inverse_[k];
      column_[i].setZero();
      if (general) {
        Ut_[e].noalias() = row_[i] * D_inverse_[k].transpose();
        row_[i].setZero();
      }
    }
  }
  // |A|_inf, the scale of the solve's backward error: the largest absolute row sum (rows are columns here, the
  // pattern being symmetric, but the values are summed by row so that a non-symmetric A is measured right).
  r_.setZero();
  const int* rows = A.innerIndexPtr();
  for (Eigen::Index e = 0; e < A.nonZeros(); ++e) r_[rows[e]] += std::abs(a[e]);
  norm_A_ = r_.maxCoeff();
  factored_ = true;
  return true;
}
// [block_ldu_factorize]

void BlockLDU::substitute(const Vector& b, Vector& x) {
  const std::vector<PaddedBlock>& U_transposed = symmetry_ == Symmetry::general ? Ut_ : L_;
  for (int k = 0; k < n_; ++k) y_[k] = b.segment<3>(3 * order_[k]);
  for (int k = 0; k < n_; ++k)  // L y = P b
    for (int e = column_start_[k]; e < column_start_[k + 1]; ++e)
      y_[row_of_entry_[e]] -= L_[e].topRows<3>() * y_[k];
  for (int k = 0; k < n_; ++k) y_[k] = D_inverse_[k] * y_[k];
  for (int k = n_ - 1; k >= 0; --k)  // U z = D^{-1} y
    for (int e = column_start_[k]; e < column_start_[k + 1]; ++e)
      y_[k] -= U_transposed[e].topRows<3>().transpose() * y_[row_of_entry_[e]];
  for (int k = 0; k < n_; ++k) x.segment<3>(3 * order_[k]) = y_[k];
}

// [block_ldu_refine]
double BlockLDU::solve(const SparseMatrix& A, const Vector& b, Vector& x, double target, int max_refinements) {
  eigen_assert(factored_ && b.size() == rows_ && x.size() == rows_);
  b_ = b;  // b may be x
  substitute(b_, x);
  const double norm_b = b_.lpNorm<Eigen::Infinity>();
  double backward_error = INFINITY;
  for (int step = 0;; ++step) {
    r_ = b_;
    r_.noalias() -= A * x;
    const double previous = backward_error;
    const double scale = norm_A_ * x.lpNorm<Eigen::Infinity>() + norm_b;
    backward_error = scale > 0 ? r_.lpNorm<Eigen::Infinity>() / scale : 0.0;  // b = 0: x = 0 is exact
    // Refinement in working precision converges when the factorization is good to at least one digit, each
    // step contracting the error by that factor; once it stops halving, the rounding in b - A x is all that is
    // left, and further steps would only cost time.
    if (backward_error > previous) {  // the last correction made things worse: take it back
      x -= dx_;
      backward_error = previous;
      break;
    }
    if (!(backward_error > target) || step == max_refinements || !(backward_error < 0.5 * previous)) break;
    substitute(r_, dx_);
    x += dx_;
  }
  return backward_error;
}
// [block_ldu_refine]

}  // namespace cloth
