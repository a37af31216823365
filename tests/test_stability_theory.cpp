// Chapter 7's theory against closed forms: R(z) from the tableaus, the stability limits along the axes,
// symplectic Euler's oscillator condition, the spectrum of a chain, the power iteration and the sagged equilibrium.
#include "analysis/spectrum.hpp"
#include "analysis/stability_function.hpp"
#include "integrators/method_registry.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace cloth;

namespace {
const ButcherTableau& tableau(const std::string& name) { return *find_method(name).tableau; }
bool stable(const ButcherTableau& t, Complex z) { return std::abs(stability_function(t, z)) <= 1 + 1e-12; }
}  // namespace

TEST_CASE("R(z) of rk4 computed from its tableau is 1 + z + z^2/2 + z^3/6 + z^4/24") {
  const ButcherTableau& rk4 = tableau("rk4");
  for (const Complex z : {Complex(-2.5, 0.3), Complex(0.1, 2.0), Complex(-1, -1), Complex(0.7, 0)}) {
    const Complex expected = 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
    CHECK(std::abs(stability_function(rk4, z) - expected) < 1e-14 * std::abs(expected));
  }
  const std::vector<double> r = stability_polynomial(rk4);
  REQUIRE(r.size() == 5);
  const double factorial[] = {1, 1, 2, 6, 24};
  for (int k = 0; k < 5; ++k) CHECK(r[static_cast<std::size_t>(k)] == doctest::Approx(1 / factorial[k]).epsilon(1e-15));
}

TEST_CASE("methods with s = p <= 4 stages share one R(z): heun = midpoint, rk4 = rule38") {
  for (const Complex z : {Complex(-1.7, 0.4), Complex(0.2, 2.5)}) {
    CHECK(std::abs(stability_function(tableau("heun"), z) - stability_function(tableau("midpoint"), z)) < 1e-14);
    CHECK(std::abs(stability_function(tableau("rk4"), z) - stability_function(tableau("rule38"), z)) < 1e-13);
  }
}

TEST_CASE("RK4's stability interval: 2 sqrt 2 on the imaginary axis, 2.7853 on the negative real axis") {
  const ButcherTableau& rk4 = tableau("rk4");
  const double imag = stability_limit_along([&](double y) { return stable(rk4, {0, y}); }, 5);
  const double real = stability_limit_along([&](double x) { return stable(rk4, {-x, 0}); }, 5);
  CHECK(imag == doctest::Approx(2 * std::sqrt(2.0)).epsilon(1e-8));
  // The real root of 1 + z + z^2/2 + z^3/6 + z^4/24 = -1 (Hairer & Wanner 1996, IV.2): -2.78529...
  CHECK(real == doctest::Approx(2.785293563).epsilon(1e-8));
  // Explicit Euler: the disc |1 + z| <= 1, so 2 on the real axis and nothing on the imaginary one.
  const ButcherTableau& euler = tableau("explicit_euler");
  CHECK(stability_limit_along([&](double x) { return stable(euler, {-x, 0}); }, 5) == doctest::Approx(2).epsilon(1e-9));
  CHECK_FALSE(stable(euler, {0, 1e-3}));
}

TEST_CASE("implicit Euler is A-stable: |1/(1 - z)| <= 1 on the left half-plane, and > 1 inside |z - 1| < 1") {
  for (double x = -50; x <= 0; x += 2.5)
    for (double y = -50; y <= 50; y += 2.5) CHECK(std::abs(implicit_euler_stability({x, y})) <= 1 + 1e-15);
  CHECK(std::abs(implicit_euler_stability({1, 0.5})) == doctest::Approx(1 / 0.5).epsilon(1e-14));
  CHECK(std::abs(implicit_euler_stability({2, 0})) == doctest::Approx(1).epsilon(1e-14));
}

TEST_CASE("symplectic Euler keeps an undamped oscillator bounded exactly when h omega <= 2") {
  for (double hw : {0.1, 1.0, 1.9, 1.999}) {
    CHECK(symplectic_euler_stable(-hw * hw, 0));
    // Below the limit the step matrix has determinant 1 and complex eigenvalues: |mu| = 1, no growth, no decay.
    CHECK(symplectic_euler_amplification({0, hw}, {0, -hw}) == doctest::Approx(1).epsilon(1e-14));
  }
  for (double hw : {2.001, 2.5}) {
    CHECK_FALSE(symplectic_euler_stable(-hw * hw, 0));
    // Above it the eigenvalues are real with product 1: the larger is (T + sqrt(T^2 - 4))/2, T = 2 - (h omega)^2.
    const double T = 2 - hw * hw;
    CHECK(symplectic_euler_amplification({0, hw}, {0, -hw}) ==
          doctest::Approx((std::abs(T) + std::sqrt(T * T - 4)) / 2).epsilon(1e-12));
  }
  // Slow modes must not show spurious growth from cancellation in trace^2 - 4 det.
  CHECK(symplectic_euler_amplification({-1e-14, 1e-7}, {-1e-14, -1e-7}) <= 1.0);
}

TEST_CASE("spectrum of a chain: an M x 2 strip hung by its edge has omega^2 = K/m (2 - 2 cos(k pi / M)), K/m and 0") {
  // Structural springs only, edge j = 1 pinned: the free row (i, 0) is a free-free chain along x, each particle
  // tied along y to a fixed one, with no stiffness along z in the flat state.
  const int M = 6;
  const double K = 50, m = 2;
  SceneParams p;
  p.grid.M = M;
  p.grid.N = 2;
  p.stiffness = K;
  p.mass = m;
  p.pins = PinSet::edge;
  p.families = FamilySet::only(SpringFamily::structural);
  const Scene scene(p);
  ForceField field(scene);
  std::vector<double> expected;
  for (int k = 0; k < M; ++k) {
    expected.push_back(K / m * (2 - 2 * std::cos(k * M_PI / M)));
    expected.push_back(K / m);
    expected.push_back(0);
  }
  std::sort(expected.begin(), expected.end());
  const std::vector<double> omega2 = stiffness_eigenvalues(field, scene.initial_positions());
  REQUIRE(omega2.size() == expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) CHECK(omega2[k] == doctest::Approx(expected[k]).epsilon(1e-12).scale(K / m));

  // With a projected damper the rest-state damping is proportional (df/dv = (D/K) df/dx), so the dense
  // non-symmetric eigen-solver must find exactly the roots of lambda^2 + (D/K) omega^2 lambda + omega^2 = 0.
  p.damping = 3;
  const Scene damped(p);
  ForceField damped_field(damped);
  const auto dense = dense_spectrum(damped_field, damped.initial_positions(), Vector::Zero(damped.dof_count()));
  const auto closed = proportional_spectrum(expected, p.damping / K);
  REQUIRE(dense.size() == closed.size());
  for (const auto& l : dense) {
    double nearest = INFINITY;
    for (const auto& c : closed) nearest = std::min(nearest, std::abs(l - c));
    CHECK(nearest < 1e-6);
  }
}

TEST_CASE("the sagged equilibrium has f = 0, is a minimum, and the power iteration finds its largest |lambda|") {
  SceneParams p;
  p.grid.M = 7;
  p.grid.N = 7;
  p.stiffness = 200;
  p.damping = 20;
  const Scene scene(p);
  ForceField field(scene);
  const Equilibrium eq = static_equilibrium(field);
  REQUIRE(eq.converged);
  Vector f(scene.dof_count());
  const Vector zero = Vector::Zero(scene.dof_count());
  field.forces(eq.x, zero, f);
  CHECK(f.lpNorm<Eigen::Infinity>() < 1e-8 * 9.81);
  CHECK(eq.x.minCoeff() < -0.1);  // it sags
  const auto omega2 = stiffness_eigenvalues(field, eq.x);
  CHECK(omega2.front() > 0);  // every direction is stiff: a strict minimum of the energy
  double largest = 0;
  for (const auto& l : dense_spectrum(field, eq.x, zero)) largest = std::max(largest, std::abs(l));
  const PowerIterationResult pw = largest_eigenvalue_magnitude(field, eq.x, zero);
  CHECK(pw.converged);
  CHECK(pw.magnitude == doctest::Approx(largest).epsilon(1e-4));
}

TEST_CASE("a stiff sheet whose exact Hessian turns indefinite on the way reaches its sagged minimum in few iterations") {
  // 40 x 40 at K = 1e5: the exact Newton step is refused for many iterations while the sheet buckles out of the
  // state it first sagged into. Taking the definite step and doubling it while the energy falls crosses that
  // region: 27 iterations, where taking the definite step as it is needed 42.
  SceneParams p;
  p.grid.M = 40;
  p.grid.N = 40;
  p.stiffness = 1e5;
  const Scene scene(p);
  ForceField field(scene);
  const Equilibrium eq = static_equilibrium(field);
  REQUIRE(eq.converged);
  CHECK(eq.iterations <= 30);
  const Vector zero = Vector::Zero(scene.dof_count());
  Vector f(scene.dof_count());
  field.forces(eq.x, zero, f);
  CHECK(f.lpNorm<Eigen::Infinity>() < 1e-8 * 9.81);
  CHECK(eq.x.minCoeff() < -0.5);  // it sags
  // A minimum, not a saddle: the potential energy rises along every probed direction, both ways.
  const auto potential = [&](const Vector& x) {
    const Energy e = field.energy(x, zero);
    return e.gravity + e.spring;
  };
  const double E = potential(eq.x);
  for (int k = 0; k < 8; ++k) {
    const Vector d = 1e-4 * Vector::Random(scene.dof_count());
    CHECK(potential(eq.x + d) > E);
    CHECK(potential(eq.x - d) > E);
  }
}
