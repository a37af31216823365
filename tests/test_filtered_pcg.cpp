// Baraff and Witkin's modified PCG against its definition: the constrained components of every iterate keep
// their prescribed values, and the solution is the one a dense solve on the free subspace gives.
#include "integrators/filtered_pcg.hpp"

#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <random>

using namespace cloth;

TEST_CASE("the constraint filter holds the constrained components of every CG iterate at their prescribed values") {
  constexpr int particles = 8, n = 3 * particles;
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  // A random symmetric positive definite A (condition number ~1e2), stored sparse in full as newton_matrix does.
  Eigen::MatrixXd B(n, n);
  for (Eigen::Index k = 0; k < B.size(); ++k) B.data()[k] = normal(rng);
  const Eigen::MatrixXd dense = B.transpose() * B / n + 0.1 * Eigen::MatrixXd::Identity(n, n);
  const SparseMatrix A = dense.sparseView();
  Vector b(n), z(n);
  for (int k = 0; k < n; ++k) b[k] = normal(rng), z[k] = normal(rng);

  // Particle 0 fixed, 1 in contact along a random normal, 2 along two (a crease against two planes), others free.
  ConstraintFilter filter(particles);
  filter.fix(0);
  const Eigen::Vector3d n1 = Eigen::Vector3d(0.3, -0.4, 0.8).normalized();
  filter.constrain(1, n1);
  filter.constrain(2, Eigen::Vector3d::UnitZ());
  filter.constrain(2, Eigen::Vector3d(1, 0, 1));  // not orthogonal to e_z: the filter orthogonalises it
  CHECK((filter.block(2) - Eigen::Vector3d::UnitY() * Eigen::Vector3d::UnitY().transpose()).norm() < 1e-15);

  // Independent truth: dv = (I - S) z + Z y with Z an orthonormal basis of the free subspace and
  // (Z^T A Z) y = Z^T (b - A (I - S) z), solved densely.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
  for (int s = 0; s < particles; ++s) S.block<3, 3>(3 * s, 3 * s) = filter.block(s);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> projector(S);
  const Eigen::MatrixXd Z = projector.eigenvectors().rightCols(n - 3 - 1 - 2);  // eigenvalue 1: the free directions
  REQUIRE((projector.eigenvalues().tail(n - 6).array() - 1).abs().maxCoeff() < 1e-12);
  const Vector prescribed = z - S * z;
  const Vector y = (Z.transpose() * dense * Z).ldlt().solve(Z.transpose() * (b - dense * prescribed));
  const Vector truth = prescribed + Z * y;

  FilteredPCG pcg(n);
  REQUIRE(pcg.compute(A));
  for (int iterations : {1, 2, 5, 200}) {
    CAPTURE(iterations);
    Vector dv = Vector::Constant(n, 3.0);  // a warm start whose constrained components are wrong
    const bool converged = pcg.solve(A, b, filter, z, dv, 1e-12, iterations);
    CHECK(converged == (iterations == 200));
    // The constrained components are the prescribed ones, to rounding, after any number of iterations.
    const Vector constrained = dv - S * dv;
    CHECK((constrained - prescribed).cwiseAbs().maxCoeff() < 1e-14);
    if (converged) {
      CHECK((dv - truth).norm() <= 1e-9 * truth.norm());
      CHECK((S * (dense * dv - b)).norm() <= 1e-10 * b.norm());
    }
  }
  // Unfiltered, the same A and b give another answer: the constraints are doing something.
  const Vector unconstrained = dense.ldlt().solve(b);
  CHECK((unconstrained - truth).norm() > 0.1 * truth.norm());
}
