// The largest eigenvalue of a scaled symmetric sparse matrix by Lanczos (analysis/fastest_modes.hpp).
#include "analysis/fastest_modes.hpp"

#include "analysis/power_iteration.hpp"
#include "analysis/sparse_operators.hpp"

#include <Eigen/Eigenvalues>
#include <Spectra/SymEigsSolver.h>
#include <algorithm>
#include <utility>

namespace cloth {

double largest_rate(const SparseMatrix& J, double mass) {
  const Eigen::Index n = J.rows();
  if (n < 3) {  // Lanczos needs a Krylov space larger than the one eigenvalue it returns
    if (n == 0) return 0.0;
    const Eigen::MatrixXd minus_J = -Eigen::MatrixXd(J) / mass;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense(minus_J, Eigen::EigenvaluesOnly);
    return std::max(dense.eigenvalues().maxCoeff(), 0.0);
  }
  if (J.norm() == 0) return 0.0;
  ScaledSparseProduct minus_inverse_mass_J(J, -1.0 / mass);
  // 20 Lanczos vectors (fewer only for tiny matrices): measured on the 20 x 20 cloth, 8 or 12 vectors need more
  // restarts and 30 more orthogonalisation per restart for the same 110-150 products.
  Spectra::SymEigsSolver<ScaledSparseProduct> lanczos(minus_inverse_mass_J, 1, std::min<Eigen::Index>(20, n));
  lanczos.init();  // Spectra's fixed pseudo-random start: reproducible, and never orthogonal to the top mode
  lanczos.compute(Spectra::SortRule::LargestAlge, 1000, 1e-10);
  if (lanczos.info() == Spectra::CompInfo::Successful) return std::max(lanczos.eigenvalues()[0], 0.0);
  // Not converged in 1000 restarts (never seen on a cloth): the power iteration always gives an estimate.
  const LinearOperator apply = [&](const Vector& y, Vector& out) { minus_inverse_mass_J.perform_op(y.data(), out.data()); };
  Vector start = Vector::Ones(n) + Vector::LinSpaced(n, 0.0, 1.0);
  const PowerIterationResult top = dominant_eigenvalue(apply, std::move(start), {1e-9, 100, 20000});
  return top.dominant.real() > 0 ? top.magnitude : 0.0;
}

}  // namespace cloth
