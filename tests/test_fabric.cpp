// Chapter 10's physical units: the flexion springs' own stiffness (default unchanged, validated, Jacobians against
// finite differences), the fabric preset's derived parameters against hand-computed values and against the
// tensile stiffness the sheet actually has, mass scaling, and the cost model's stable step against the measured one.
#include <doctest/doctest.h>

#include "analysis/fastest_modes.hpp"
#include "analysis/lattice_frequency.hpp"
#include "base/input_error.hpp"
#include "integrators/explicit_runge_kutta.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/symplectic_euler.hpp"
#include "model/fabric.hpp"
#include "model/force_field.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>

#include "random_state.hpp"

using namespace cloth;

namespace {

SceneParams small_cloth(double K, double D) {
  SceneParams p;
  p.grid = Grid{4, 5, 0.1};
  p.stiffness = K;
  p.damping = D;
  return p;
}

double max_abs(const Eigen::MatrixXd& A) { return A.cwiseAbs().maxCoeff(); }

}  // namespace

TEST_CASE("without a flexion stiffness every family has K; with one, only the flexion springs change") {
  SceneParams p = small_cloth(50, 2);
  const Scene plain(p);
  for (SpringFamily f : all_spring_families) CHECK(plain.stiffness(f) == 50.0);
  p.flexion_stiffness = 0.5;
  const Scene soft(p);
  CHECK(soft.stiffness(SpringFamily::structural) == 50.0);
  CHECK(soft.stiffness(SpringFamily::shear) == 50.0);
  CHECK(soft.stiffness(SpringFamily::flexion) == 0.5);
  // The forces of the flexion family alone scale with its stiffness, to rounding.
  SceneParams only = p;
  only.families = FamilySet::only(SpringFamily::flexion);
  only.gravity = 0;
  SceneParams only_K = only;
  only_K.flexion_stiffness.reset();
  const Scene a(only), b(only_K);
  ForceField fa(a), fb(b);
  std::mt19937 rng(3);
  const testing::State s = testing::random_state(a, rng, 1.1, 0.1, 0.0);
  Vector f1(a.dof_count()), f2(a.dof_count());
  fa.forces(s.x, s.v, f1);
  fb.forces(s.x, s.v, f2);
  CHECK(f2.norm() > 1.0);
  CHECK((f1 - f2 * (0.5 / 50.0)).cwiseAbs().maxCoeff() <= 1e-13 * f2.cwiseAbs().maxCoeff());
}

TEST_CASE("a flexion stiffness that is not a finite number > 0 is refused") {
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    SceneParams p = small_cloth(50, 0);
    p.flexion_stiffness = bad;
    CHECK_THROWS_AS(validate(p), InputError);
  }
}

TEST_CASE("with a separate flexion stiffness, df/dx and df/dv still equal central differences of the forces") {
  // The Jacobians read each family's own K; a soft flexion family next to stiff ones must show in them.
  SceneParams p = small_cloth(1000, 3);
  p.flexion_stiffness = 2.0;
  const Scene scene(p);
  ForceField field(scene);
  std::mt19937 rng(5);
  const testing::State s = testing::random_state(scene, rng, 1.05, 0.1, 1.0);
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(s.x, s.v, dfdx, dfdv);
  const Eigen::Index n = s.x.size();
  Eigen::MatrixXd Jx(n, n), Jv(n, n);
  const double eps = 1e-6;
  Vector x = s.x, v = s.v, fp(n), fm(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    x[k] += eps, field.forces(x, v, fp), x[k] -= 2 * eps, field.forces(x, v, fm), x[k] = s.x[k];
    Jx.col(k) = (fp - fm) / (2 * eps);
    v[k] += eps, field.forces(x, v, fp), v[k] -= 2 * eps, field.forces(x, v, fm), v[k] = s.v[k];
    Jv.col(k) = (fp - fm) / (2 * eps);
  }
  // Entries are of order K = 1000; the central difference's error is O(eps^2 K / l^2) + O(u K l / eps) < 1e-5 here.
  CHECK(max_abs(Eigen::MatrixXd(dfdx) - Jx) <= 1e-5 * 1000);
  CHECK(max_abs(Eigen::MatrixXd(dfdv) - Jv) <= 1e-7);
  // And the soft family is really soft: the same cloth with one K has a different df/dx.
  p.flexion_stiffness.reset();
  const Scene stiff(p);
  ForceField stiff_field(stiff);
  SparseMatrix dfdx_stiff = stiff_field.pattern(), dfdv_stiff = stiff_field.pattern();
  stiff_field.jacobians(s.x, s.v, dfdx_stiff, dfdv_stiff);
  CHECK(max_abs(Eigen::MatrixXd(dfdx_stiff) - Eigen::MatrixXd(dfdx)) > 100);
}

TEST_CASE("the fabric preset's parameters equal the hand-computed ones") {
  const FabricMeasurements cotton;  // 0.25 kg/m^2, C = 2e4 N/m, B = 5e-6 N m, D = 0.01
  const SceneParams p20 = fabric_scene(cotton, {0.95, 20, 20.0});
  CHECK(p20.grid.d == doctest::Approx(0.05).epsilon(1e-15));
  CHECK(p20.mass == doctest::Approx(6.25e-4).epsilon(1e-14));  // 0.25 * 0.05^2
  // k_flexion = 16 B / (kappa d^2)^2 = 16 * 5e-6 / (20 * 0.0025)^2 = 8e-5 / 0.0025 = 0.032 N/m
  REQUIRE(p20.flexion_stiffness.has_value());
  CHECK(*p20.flexion_stiffness == doctest::Approx(0.032).epsilon(1e-13));
  // k = (C - 4 k_flexion) / 2 = (2e4 - 0.128) / 2
  CHECK(p20.stiffness == doctest::Approx(9999.936).epsilon(1e-14));
  CHECK(p20.damping == 0.01);
  CHECK(p20.initial_velocity_z == 0.0);
  // The same square with 39 particles per side: d = 0.025, m a quarter, k_flexion 16 times larger.
  const SceneParams p39 = fabric_scene(cotton, {0.95, 39, 20.0});
  CHECK(p39.grid.d == doctest::Approx(0.025).epsilon(1e-15));
  CHECK(p39.mass == doctest::Approx(1.5625e-4).epsilon(1e-14));
  CHECK(*p39.flexion_stiffness == doctest::Approx(0.512).epsilon(1e-13));
  CHECK(p39.stiffness == doctest::Approx((2e4 - 4 * 0.512) / 2).epsilon(1e-14));
  // Total mass rho_A (n d)^2 converges to rho_A side^2 as the grid is refined.
  CHECK(400 * p20.mass == doctest::Approx(0.25).epsilon(1e-14));
  CHECK_THROWS_AS((void)fabric_scene(cotton, {0.95, 2, 20.0}), InputError);
  FabricMeasurements stiff_bending = cotton;
  stiff_bending.bending_rigidity = 1.0;  // flexion springs stiffer than the fabric in tension
  CHECK_THROWS_AS((void)fabric_scene(stiff_bending, {0.95, 20, 20.0}), InputError);
}

TEST_CASE("a large uniformly stretched sheet stores the energy C e^2 / 2 per unit area, C = k_s + k_sh + 4 k_f") {
  // The derivation behind the preset's stiffness, checked on the model's own energy: a 300 x 300 sheet stretched
  // by the strain e along x (and held along y). Edge particles miss some springs and the n rows of x springs span
  // only n - 1 spacings, relative effects of order 1 / n, so the energy density is within 1 % of the continuum's.
  SceneParams p;
  const int n = 300;
  p.grid = Grid{n, n, 0.01};
  p.stiffness = 100;
  p.flexion_stiffness = 7;
  p.pins = PinSet::none;
  const Scene scene(p);
  ForceField field(scene);
  const double e = 1e-4;
  Vector x = scene.initial_positions();
  for (Eigen::Index k = 0; k < x.size(); k += 3) x[k] *= 1 + e;
  const double energy = field.energy(x, Vector::Zero(x.size())).spring;
  const double area = (n - 1) * (n - 1) * p.grid.d * p.grid.d;
  const double C = 100 + 100 + 4 * 7;
  CHECK(energy / area == doctest::Approx(C * e * e / 2).epsilon(0.01));
}

TEST_CASE("mass scaling: doubling m halves the spring and damper accelerations, and (2m, 2K, 2D) moves as (m, K, D)") {
  SceneParams p = small_cloth(300, 4);
  p.mass = 0.01;
  p.flexion_stiffness = 30;
  p.gravity = 0;  // gravity's acceleration does not depend on m
  SceneParams heavy = p;
  heavy.mass = 2 * p.mass;
  const Scene light_scene(p), heavy_scene(heavy);
  ForceField light_field(light_scene), heavy_field(heavy_scene);
  std::mt19937 rng(9);
  const testing::State s = testing::random_state(light_scene, rng, 1.1, 0.1, 1.0);
  Vector a1(s.x.size()), a2(s.x.size());
  light_field.acceleration(s.x, s.v, a1);
  heavy_field.acceleration(s.x, s.v, a2);
  CHECK(a1.norm() > 100);
  CHECK((a2 - 0.5 * a1).cwiseAbs().maxCoeff() <= 1e-15 * a1.cwiseAbs().maxCoeff());

  // (2m, 2K, 2D), with gravity, under RK4: the accelerations are the same numbers, so the motion is too.
  p.gravity = heavy.gravity = 9.81;
  heavy.stiffness = 2 * p.stiffness, heavy.damping = 2 * p.damping, heavy.flexion_stiffness = 2 * *p.flexion_stiffness;
  const Scene s1(p), s2(heavy);
  ForceField f1(s1), f2(s2);
  ExplicitRungeKutta rk1(f1, tableau_from_argument("rk4")), rk2(f2, tableau_from_argument("rk4"));
  Vector x1 = s1.initial_positions(), v1 = s1.initial_velocities(), x2 = x1, v2 = v1;
  for (int k = 0; k < 200; ++k) rk1.step(1e-3, x1, v1), rk2.step(1e-3, x2, v2);
  CHECK((x1 - s1.initial_positions()).norm() > 0.1);  // it moved
  CHECK((x1 - x2).cwiseAbs().maxCoeff() <= 1e-13);
  CHECK((v1 - v2).cwiseAbs().maxCoeff() <= 1e-12);
}

TEST_CASE("the lattice's fastest frequency: 10.125 K / m with one K, 8 K / m with soft flexion springs") {
  // Closed forms: along the diagonal q = (a, a) / d, with c = cos a, one K gives m omega^2 = 2 K (1 - c) +
  // 8 K (1 - c^2), largest at c = -1/8: 10.125 K. Without flexion springs the largest is 8 K at q = (0, pi / d).
  CHECK(lattice_fastest_frequency({1e5, 1e5, 1e5, 6.25e-4}) ==
        doctest::Approx(std::sqrt(10.125 * 1e5 / 6.25e-4)).epsilon(1e-9));
  CHECK(lattice_fastest_frequency({3.0, 3.0, 0.0, 2.0}) == doctest::Approx(std::sqrt(8 * 3.0 / 2.0)).epsilon(1e-9));
  // A finite cloth's omega_max (power iteration on its Jacobian) lies just below the unbounded lattice's.
  const SceneParams p = fabric_scene(FabricMeasurements{}, {0.95, 20, 20.0});
  const Scene scene(p);
  ForceField field(scene);
  const double finite = fastest_rest_frequency(field);
  const double lattice = lattice_fastest_frequency({p.stiffness, p.stiffness, *p.flexion_stiffness, p.mass});
  CHECK(finite <= lattice * (1 + 1e-9));
  CHECK(finite >= 0.97 * lattice);
}

namespace {

// Whether symplectic Euler with step h keeps the fabric bounded for `steps` steps from rest under gravity, with
// a 1e-6 m perturbation to seed every mode: an unstable mode grows by a fixed factor per step and stretches some
// spring by half its length long before the end.
bool symplectic_euler_stays_bounded(const Scene& scene, double h, int steps) {
  ForceField field(scene);
  SymplecticEuler stepper(field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(-1e-6, 1e-6);
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] += unit(rng);
  for (int k = 0; k < steps; ++k) {
    stepper.step(h, x, v);
    if (!x.allFinite() || (x - scene.initial_positions()).cwiseAbs().maxCoeff() > 1.0) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("the cost model's stable step 2 / omega_max matches symplectic Euler's measured one within 10 %") {
  for (double K : {1e4, 1e5}) {
    CAPTURE(K);
    SceneParams p;
    p.grid = Grid{20, 20, 0.05};
    p.mass = 6.25e-4;
    p.stiffness = K;
    p.damping = 0;
    p.initial_velocity_z = 0;
    const Scene scene(p);
    const double predicted = 2 / lattice_fastest_frequency({K, K, K, p.mass});
    // Bisection on h between a stable and an unstable step.
    double stable = 0.5 * predicted, unstable = 2 * predicted;
    REQUIRE(symplectic_euler_stays_bounded(scene, stable, 3000));
    REQUIRE(!symplectic_euler_stays_bounded(scene, unstable, 3000));
    for (int k = 0; k < 10; ++k) {
      const double mid = std::sqrt(stable * unstable);
      (symplectic_euler_stays_bounded(scene, mid, 3000) ? stable : unstable) = mid;
    }
    CHECK(stable == doctest::Approx(predicted).epsilon(0.10));
  }
}
