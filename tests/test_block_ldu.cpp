// The block LDL^T / LDU solver against Eigen's sparse LU with partial pivoting, an independent factorization, on
// the three Newton matrices a damped cloth gives; and its refusal of a singular pivot block.
#include "integrators/block_ldu.hpp"
#include "random_state.hpp"

#include <doctest/doctest.h>

#include <Eigen/SparseLU>

using namespace cloth;

namespace {

struct Case {
  StiffnessTreatment treatment;
  BlockLDU::Symmetry symmetry;
  const char* name;
};

// |A x - b|_inf / (|A|_inf |x|_inf + |b|_inf): the normwise backward error (Rigal & Gaches 1967). A backward
// stable solve leaves it at a small multiple of the unit roundoff whatever the condition of A.
double backward_error(const SparseMatrix& A, const Vector& x, const Vector& b) {
  double norm_A = 0;
  const SparseMatrix At = A.transpose();
  for (int c = 0; c < At.outerSize(); ++c) norm_A = std::max(norm_A, At.col(c).cwiseAbs().sum());
  return (A * x - b).lpNorm<Eigen::Infinity>() /
         (norm_A * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
}

}  // namespace

TEST_CASE("block LDU solves the Newton matrices of a folded, damped cloth as Eigen's pivoting LU does") {
  SceneParams p;
  p.grid.M = p.grid.N = 12;
  p.stiffness = 2000;
  p.damping = 5;
  const Scene scene(p);
  ForceField field(scene);
  std::mt19937 rng(7);
  // Compressed to 0.7 of the rest size and jittered: compressed springs make the exact and symmetric matrices
  // indefinite at this large step, the damper makes the exact one non-symmetric.
  const auto s = testing::random_state(scene, rng, 0.7, 0.3, 2.0);
  const double h = 0.05;
  Vector b(field.dof_count());
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Eigen::Index k = 0; k < b.size(); ++k) b[k] = unit(rng);

  for (const Case c : {Case{StiffnessTreatment::definite, BlockLDU::Symmetry::symmetric, "definite"},
                       Case{StiffnessTreatment::symmetric, BlockLDU::Symmetry::symmetric, "symmetric"},
                       Case{StiffnessTreatment::exact, BlockLDU::Symmetry::general, "exact"}}) {
    INFO("treatment " << c.name);
    SparseMatrix A = field.pattern();
    field.newton_matrix(s.x, s.v, h, c.treatment, A);
    if (c.symmetry == BlockLDU::Symmetry::symmetric) REQUIRE((SparseMatrix(A.transpose()) - A).norm() == 0.0);
    else REQUIRE((SparseMatrix(A.transpose()) - A).norm() > 1e-3 * A.norm());

    Eigen::SparseLU<SparseMatrix> lu(A);
    REQUIRE(lu.info() == Eigen::Success);
    const Vector reference = lu.solve(b);

    BlockLDU block;
    block.analyze(field.pattern(), c.symmetry);
    REQUIRE(block.factorize(A));
    Vector x(b.size());
    block.solve(b, x);
    // Without pivoting across blocks, stability is guaranteed only for the definite matrix (block LDL^T of an
    // SPD matrix has no element growth); the indefinite ones lose a few digits to growth (measured here: backward
    // error 5.6e-14 symmetric, 2.1e-13 exact, against 7e-17 and 1.5e-16 for the pivoting LU). Newton asks its
    // update for 1e-8 relative accuracy, so the bound below (1e-10) is what matters for implicit Euler.
    const bool definite = c.treatment == StiffnessTreatment::definite;
    CHECK(backward_error(A, x, b) < (definite ? 50 * testing::unit_roundoff : 1e-10));
    CHECK((x - reference).lpNorm<Eigen::Infinity>() <= (definite ? 1e-13 : 1e-9) * reference.lpNorm<Eigen::Infinity>());

    // Refactorizing new values in the same pattern (the Newton loop's use) gives the new solution.
    field.newton_matrix(s.x, s.v, 0.5 * h, c.treatment, A);
    REQUIRE(block.factorize(A));
    block.solve(b, x);
    CHECK(backward_error(A, x, b) < (definite ? 50 * testing::unit_roundoff : 1e-10));
  }
}

TEST_CASE("block LDU refuses a singular pivot block, then factors the next matrix as if nothing happened") {
  SceneParams p;
  p.grid.M = p.grid.N = 6;
  const Scene scene(p);
  ForceField field(scene);
  SparseMatrix A = field.pattern();
  field.newton_matrix(scene.initial_positions(), scene.initial_velocities(), 0.01, StiffnessTreatment::definite, A);
  BlockLDU block;
  block.analyze(A, BlockLDU::Symmetry::symmetric);

  // Particle 5's block row and column made rank-deficient: its third row and column are zero, so whatever the
  // elimination order, the pivot block of particle 5 has a zero row.
  SparseMatrix singular = A;
  for (int c = 0; c < singular.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(singular, c); it; ++it)
      if (it.row() == 3 * 5 + 2 || it.col() == 3 * 5 + 2) it.valueRef() = 0;
  CHECK_FALSE(block.factorize(singular));

  REQUIRE(block.factorize(A));
  Vector b = Vector::Ones(A.rows()), x(A.rows());
  block.solve(b, x);
  CHECK(backward_error(A, x, b) < 50 * testing::unit_roundoff);
}
