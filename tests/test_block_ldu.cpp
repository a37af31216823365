// The block LDL^T / LDU solver against Eigen's sparse LU with partial pivoting, an independent factorization, on
// the Newton matrices of folded, damped cloths; its iterative refinement; and its refusal of a singular pivot.
#include "integrators/block_ldu.hpp"
#include "random_state.hpp"

#include <doctest/doctest.h>

#include <Eigen/SparseLU>

using namespace cloth;

namespace {

// |A x - b|_inf / (|A|_inf |x|_inf + |b|_inf): the normwise backward error (Rigal & Gaches 1967), computed here
// independently of the solver's own estimate.
double backward_error(const SparseMatrix& A, const Vector& x, const Vector& b) {
  const SparseMatrix At = A.transpose();
  double norm_A = 0;
  for (int c = 0; c < At.outerSize(); ++c) norm_A = std::max(norm_A, At.col(c).cwiseAbs().sum());
  return (A * x - b).lpNorm<Eigen::Infinity>() / (norm_A * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
}

}  // namespace

TEST_CASE("block LDU solves the Newton matrices of folded, damped cloths as accurately as Eigen's pivoting LU") {
  // Compressed to 0.7 of the rest size and jittered, at a large step (h^2 K / m = 5): compressed springs make the
  // exact and symmetric matrices indefinite, the damper makes the exact one non-symmetric. Without pivoting
  // across blocks, the factors of such matrices can grow: the unrefined solve of one of these cases keeps only
  // 4 digits (backward error 2.5e-5 on a matrix of condition 240). Refinement must win them back.
  struct Treatment {
    StiffnessTreatment treatment;
    BlockLDU::Symmetry symmetry;
  };
  const Treatment treatments[] = {{StiffnessTreatment::definite, BlockLDU::Symmetry::symmetric},
                                  {StiffnessTreatment::symmetric, BlockLDU::Symmetry::symmetric},
                                  {StiffnessTreatment::exact, BlockLDU::Symmetry::general}};
  double worst_unrefined = 0, worst_refined = 0;
  int cases = 0;
  for (const PinSet pins : {PinSet::corners, PinSet::corner, PinSet::edge, PinSet::none})
    for (const DampingModel law : {DampingModel::projected, DampingModel::report})
      for (const unsigned seed : {7U, 13U, 21U}) {
        SceneParams p;
        p.grid.M = 9;
        p.grid.N = 7;
        p.stiffness = 2000;
        p.damping = 5;
        p.damping_model = law;
        p.pins = pins;
        const Scene scene(p);
        ForceField field(scene);
        std::mt19937 rng(seed);
        const auto s = testing::random_state(scene, rng, 0.7, 0.3, 2.0);
        Vector b(field.dof_count());
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        for (Eigen::Index k = 0; k < b.size(); ++k) b[k] = unit(rng);
        for (const Treatment& t : treatments) {
          INFO("pins " << std::string(pin_set_name(pins)) << ", damping law " << static_cast<int>(law) << ", seed " << seed
                       << ", treatment " << static_cast<int>(t.treatment));
          SparseMatrix A = field.pattern();
          field.newton_matrix(s.x, s.v, 0.05, t.treatment, A);
          const bool symmetric = (SparseMatrix(A.transpose()) - A).norm() == 0.0;
          REQUIRE(symmetric == (t.symmetry == BlockLDU::Symmetry::symmetric));

          Eigen::SparseLU<SparseMatrix> lu(A);
          REQUIRE(lu.info() == Eigen::Success);
          const Vector reference = lu.solve(b);
          const double reference_error = backward_error(A, reference, b);

          BlockLDU block;
          block.analyze(field.pattern(), t.symmetry);
          REQUIRE(block.factorize(A));
          Vector x(b.size());
          block.solve(A, b, x, 0.0, 0);  // no refinement
          worst_unrefined = std::max(worst_unrefined, backward_error(A, x, b));
          const double reported = block.solve(A, b, x);
          const double measured = backward_error(A, x, b);
          CHECK(reported == doctest::Approx(measured).epsilon(1e-6));
          // Refined, the solve is backward stable to 13 digits (solve() aims at 1e-14 and stops when a step no
          // longer halves the error). The worst case here starts at 1e-4 and gains about three digits per
          // refinement step (6e-4, 1e-6, 3e-9, 6e-12, 2e-14 with AVX; 1e-4, 3e-8, 2e-11, 1.4e-14 with SSE2), so
          // it needs four or five of solve()'s six; the pivoting LU reaches 1e-16 directly.
          INFO("block " << measured << ", pivoting LU " << reference_error);
          CHECK(measured <= 1e-13);
          worst_refined = std::max(worst_refined, measured);
          CHECK((x - reference).lpNorm<Eigen::Infinity>() <= 1e-10 * reference.lpNorm<Eigen::Infinity>());
          ++cases;
        }
      }
  CHECK(cases == 72);
  // The refinement is doing work: without it, some of these solves are far from backward stable.
  CHECK(worst_unrefined > 1e-12);
  MESSAGE("largest backward error over the cases, unrefined " << worst_unrefined << ", refined " << worst_refined);
}

TEST_CASE("block LDU refuses a singular pivot block, in both modes, and factors the next matrix exactly") {
  SceneParams p;
  p.grid.M = p.grid.N = 6;
  p.damping = 3;
  const Scene scene(p);
  ForceField field(scene);
  for (const auto& [treatment, symmetry] :
       {std::pair{StiffnessTreatment::definite, BlockLDU::Symmetry::symmetric},
        std::pair{StiffnessTreatment::exact, BlockLDU::Symmetry::general}}) {
    SparseMatrix A = field.pattern();
    field.newton_matrix(scene.initial_positions(), scene.initial_velocities(), 0.01, treatment, A);
    BlockLDU block;
    block.analyze(A, symmetry);

    // Particle 5's third row and column zeroed: whatever the elimination order, its pivot block has a zero row
    // and column, and is exactly singular.
    SparseMatrix singular = A;
    for (int c = 0; c < singular.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(singular, c); it; ++it)
        if (it.row() == 3 * 5 + 2 || it.col() == 3 * 5 + 2) it.valueRef() = 0;
    CHECK_FALSE(block.factorize(singular));

    REQUIRE(block.factorize(A));
    const Vector b = Vector::Ones(A.rows());
    Vector x(A.rows());
    block.solve(A, b, x, 0.0, 0);
    CHECK(backward_error(A, x, b) < 8 * testing::unit_roundoff);
  }
}
