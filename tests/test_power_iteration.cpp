// The shared power iteration (analysis/power_iteration.hpp) against matrices whose eigenvalues are known by
// construction, and the cloth's fastest rest frequency against the dense symmetric eigen-solver.
#include "analysis/fastest_modes.hpp"
#include "analysis/power_iteration.hpp"
#include "analysis/spectrum.hpp"

#include <Eigen/QR>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace cloth;

namespace {

// A dense operator for the tests: out = A y.
LinearOperator dense(const Eigen::MatrixXd& A) {
  return [A](const Vector& y, Vector& out) { out = A * y; };
}

// An orthogonal matrix, so that Q diag Q^T hides the eigenvalues from the iteration's start vector.
Eigen::MatrixXd orthogonal(int n) {
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = std::sin(1.0 + 3.1 * i + 0.7 * j * j);
  return Eigen::HouseholderQR<Eigen::MatrixXd>(M).householderQ();
}

}  // namespace

TEST_CASE("power iteration: two close real eigenvalues on top of a symmetric matrix") {
  const int n = 40;
  Vector d = Vector::LinSpaced(n, 0.0, 8.0);
  d[n - 1] = 10.0, d[n - 2] = 9.99;  // the top two 0.1% apart, as the cloth's are
  const Eigen::MatrixXd Q = orthogonal(n);
  const PowerIterationResult r =
      dominant_eigenvalue(dense(Q * d.asDiagonal() * Q.transpose()), Vector::Ones(n), {1e-12, 10, 20000});
  CHECK(r.converged);
  CHECK(r.magnitude == doctest::Approx(10.0).epsilon(1e-10));
  CHECK(r.dominant.real() == doctest::Approx(10.0).epsilon(1e-10));
}

TEST_CASE("power iteration: a dominant conjugate pair of a non-symmetric matrix") {
  // Q blockdiag([[a, -b], [b, a]], 3, 2.9, ..) Q^T: eigenvalues a +- i b with |a + i b| = 5 above the real ones.
  const int n = 30;
  const double a = -3, b = 4;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  B(0, 0) = a, B(0, 1) = -b, B(1, 0) = b, B(1, 1) = a;
  for (int k = 2; k < n; ++k) B(k, k) = 3.0 - 0.1 * k;
  const Eigen::MatrixXd Q = orthogonal(n);
  const PowerIterationResult r = dominant_eigenvalue(dense(Q * B * Q.transpose()), Vector::Ones(n), {1e-12, 10, 5000});
  CHECK(r.converged);
  CHECK(r.magnitude == doctest::Approx(5.0).epsilon(1e-10));
  CHECK(r.dominant.real() == doctest::Approx(a).epsilon(1e-9));
  CHECK(r.dominant.imag() == doctest::Approx(b).epsilon(1e-9));
}

TEST_CASE("power iteration: the zero operator gives 0, not NaN") {
  const PowerIterationResult r = dominant_eigenvalue(dense(Eigen::MatrixXd::Zero(5, 5)), Vector::Ones(5));
  CHECK(r.magnitude == 0.0);
  CHECK(r.converged);
}

TEST_CASE("the cloth's fastest rest frequency is the dense solver's largest omega") {
  // 20 x 20 report cloth, K = 50: its top modes lie close together, where an ill-conditioned fit once returned a
  // spurious root above the spectrum (omega_max 22.63 instead of 22.35).
  SceneParams p;
  const Scene scene(p);
  ForceField field(scene);
  const std::vector<double> omega2 = stiffness_eigenvalues(field, scene.initial_positions());
  const double dense_omega_max = std::sqrt(*std::max_element(omega2.begin(), omega2.end()));
  CHECK(fastest_rest_frequency(field) == doctest::Approx(dense_omega_max).epsilon(1e-8));
}
