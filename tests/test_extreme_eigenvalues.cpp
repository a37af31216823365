// The extreme eigenvalues by Lanczos and Arnoldi (Spectra) against the dense eigen-solvers, on cloths small
// enough for both: the fastest rates, the largest omega^2 of a sagged cloth, and the largest |lambda| of its
// damped first-order system, which is not symmetric and has both real and complex eigenvalues.
#include "analysis/fastest_modes.hpp"
#include "analysis/spectrum.hpp"

#include <Eigen/Eigenvalues>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

using namespace cloth;

namespace {

SceneParams small_cloth(double K, double D) {
  SceneParams p;
  p.grid.M = 8;
  p.grid.N = 7;
  p.stiffness = K;
  p.damping = D;
  return p;
}

/// The small cloth at (K, D), its forces, and its sagged equilibrium: the state every check below linearises at.
struct SaggedCloth {
  Scene scene;
  ForceField field;
  Equilibrium eq;
  SaggedCloth(double K, double D) : scene(small_cloth(K, D)), field(scene), eq(static_equilibrium(field)) {
    REQUIRE(eq.converged);
  }
};

}  // namespace

TEST_CASE("Lanczos: the fastest damping rate is the dense solver's largest eigenvalue of -M^{-1} df/dv") {
  SaggedCloth cloth(200, 20);
  auto& [scene, field, eq] = cloth;
  const Vector v = Vector::Zero(eq.x.size());
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(eq.x, v, dfdx, dfdv);
  const Eigen::MatrixXd C = -Eigen::MatrixXd(dfdv) / scene.params().mass;
  const double dense = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(C, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
  CHECK(fastest_damping_rate(field, eq.x, v) == doctest::Approx(dense).epsilon(1e-10));
  // A cloth without dampers has no damping rate at all.
  const Scene undamped(small_cloth(200, 0));
  ForceField undamped_field(undamped);
  CHECK(fastest_damping_rate(undamped_field, eq.x, v) == 0.0);
}

TEST_CASE("Lanczos: the largest omega^2 of the sagged cloth, in order") {
  SaggedCloth cloth(50, 0);
  auto& [scene, field, eq] = cloth;
  std::vector<double> dense = stiffness_eigenvalues(field, eq.x);
  std::sort(dense.begin(), dense.end(), std::greater<>());
  const std::vector<double> top = largest_stiffness_eigenvalues(field, eq.x, 5);
  REQUIRE(top.size() == 5);
  for (std::size_t k = 0; k < top.size(); ++k) CHECK(top[k] == doctest::Approx(dense[k]).epsilon(1e-9));
}

TEST_CASE("Arnoldi: the largest |lambda| of the damped sagged cloth, conjugate pairs whole") {
  SaggedCloth cloth(200, 20);
  auto& [scene, field, eq] = cloth;
  const Vector zero = Vector::Zero(eq.x.size());
  std::vector<std::complex<double>> dense = dense_spectrum(field, eq.x, zero);
  std::sort(dense.begin(), dense.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  for (int count : {1, 6, 9}) {
    const std::vector<std::complex<double>> top = largest_eigenvalues(field, eq.x, zero, count);
    REQUIRE(static_cast<int>(top.size()) >= count);
    REQUIRE(static_cast<int>(top.size()) <= count + 1);
    for (std::size_t k = 0; k < top.size(); ++k) {
      CHECK(std::abs(top[k]) == doctest::Approx(std::abs(dense[k])).epsilon(1e-9));
      double nearest = INFINITY;  // each one is an eigenvalue of J, not only of the right size
      for (const auto& l : dense) nearest = std::min(nearest, std::abs(l - top[k]));
      CHECK(nearest < 1e-8 * std::abs(dense[0]));
      if (top[k].imag() != 0) {  // its partner is there too
        const bool partner = std::any_of(top.begin(), top.end(),
                                         [&](auto l) { return std::abs(l - std::conj(top[k])) < 1e-8 * std::abs(l); });
        CHECK(partner);
      }
    }
  }
}

TEST_CASE("the sagged equilibrium of a very light cloth converges: forces at rounding level are balanced") {
  // A cloth of 1 mg particles on 200 N/m springs: its weight, 1e-5 N, is below what 1e-9 of it can resolve among
  // spring forces of 40 N (rounding 1e-14 N), so the test on the weight alone could never be met.
  SceneParams light = small_cloth(200, 0);
  light.mass = 1e-6;
  const Scene scene(light);
  ForceField field(scene);
  const Equilibrium eq = static_equilibrium(field);
  CHECK(eq.converged);
  Vector f(field.dof_count());
  field.forces(eq.x, Vector::Zero(field.dof_count()), f);
  CHECK(f.lpNorm<Eigen::Infinity>() <= 64 * std::numeric_limits<double>::epsilon() * 200 * 2 * light.grid.d);
  CHECK(eq.x.minCoeff() < 0);  // it sags, a little
}
