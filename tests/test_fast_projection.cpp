// Inextensible cloth (Chapter 10): fast projection and RATTLE leave every constraint met to their tolerance,
// conserve the linear momentum of a free sheet, converge at their orders as the step shrinks, and converge to the
// spring model's motion at first order in 1/K as the stretch springs stiffen under flexion springs of fixed K.
#include <doctest/doctest.h>

#include "analysis/trajectory_measures.hpp"
#include "integrators/fast_projection.hpp"
#include "integrators/method_registry.hpp"

#include <cmath>

using namespace cloth;

namespace {

// Chapter 10's fabric on a small grid (6 x 6, 5 cm, 0.625 g a particle, D = 0.01), hung by one edge.
SceneParams small_curtain(double K) {
  SceneParams p;
  p.grid = Grid{6, 6, 0.05};
  p.mass = 6.25e-4;
  p.stiffness = K;
  p.damping = 0.01;
  p.pins = PinSet::edge;
  p.initial_velocity_z = 0;
  return p;
}

// Free positions after n steps of h of a registry method from the scene's initial state.
Vector run(const Scene& scene, const std::string& method, double h, int n) {
  ForceField field(scene);
  const auto stepper = make_stepper(method, field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  for (int k = 0; k < n; ++k) REQUIRE(stepper->step(h, x, v));
  return x;
}

// The total momentum m sum v.
Eigen::Vector3d momentum(const Vector& v, double m) { return m * v.reshaped(3, v.size() / 3).rowwise().sum(); }

}  // namespace

TEST_CASE("fast projection and RATTLE leave every constraint within its tolerance, RATTLE's velocity tangent") {
  const Scene scene(small_curtain(1e5));
  for (const ConstrainedScheme scheme : {ConstrainedScheme::fast_projection, ConstrainedScheme::rattle}) {
    ForceField field(scene);
    ConstrainedCloth stepper(field, "constrained", scheme, 1e-10);
    ConstrainedCloth probe(field, "probe", scheme);
    // Structural springs, less the 5 between pinned particles (hard), and both diagonals of each square.
    CHECK(stepper.hard_constraint_count() == 2 * 6 * 5 - 5);
    CHECK(stepper.constraint_count() == 2 * 6 * 5 - 5 + 2 * 25);
    Vector x = scene.initial_positions(), v = scene.initial_velocities();
    double violation = 0, rate = 0;
    for (int k = 0; k < 250; ++k) {  // 0.25 s: the curtain falls through a right angle and folds
      REQUIRE(stepper.step(1.0 / 1000, x, v));
      CHECK(stepper.last_residual() <= 1e-10);  // the compliant rows' C - alpha~ Lambda as well
      violation = std::max(violation, probe.largest_violation(x));
      rate = std::max(rate, probe.largest_stretching_rate(x, v));
    }
    CHECK(violation <= 1e-10);
    CHECK(violation > 0);  // measured, not assumed
    CHECK(largest_distance(x, scene.initial_positions()) > 0.2);  // the sheet moved
    if (scheme == ConstrainedScheme::rattle) CHECK(rate < 1e-11);  // against |v| ~ 1 m/s
  }
}

TEST_CASE("the constraint forces conserve the linear momentum of a free sheet: it changes by M g t only") {
  SceneParams p = small_curtain(1e4);
  p.pins = PinSet::none;
  const Scene scene(p);
  Vector v0(scene.dof_count());
  for (Eigen::Index k = 0; k < v0.size(); ++k) v0[k] = std::sin(1.7 * static_cast<double>(k));  // folds the sheet
  for (const char* method : {"fast_projection", "rattle"}) {
    CAPTURE(method);
    ForceField field(scene);
    const auto stepper = make_stepper(method, field);
    Vector x = scene.initial_positions(), v = v0;
    const double h = 1.0 / 600;
    // RATTLE's first step makes v0 tangent to the constraints: a projection along M^-1 J^T, momentum-free too.
    const Eigen::Vector3d P0 = momentum(v, p.mass);
    const int steps = 120;
    for (int k = 0; k < steps; ++k) REQUIRE(stepper->step(h, x, v));
    const Eigen::Vector3d expected = P0 - Eigen::Vector3d(0, 0, 36 * p.mass * p.gravity * h * steps);
    CHECK(largest_distance(x, scene.initial_positions()) > 0.1);
    CHECK((momentum(v, p.mass) - expected).norm() < 1e-13);  // against m sum |v| ~ 2e-2 kg m/s
  }
}

TEST_CASE("with hard constraints only, RATTLE converges at second order, fast projection at first") {
  // Undamped and without shear springs, RATTLE is velocity Verlet on the manifold of the structural constraints.
  // (The compliant shear springs' force enters both half kicks at x_{n+1}, and the second half kick sees the
  // dampers at the mid-step velocity: each is first order, in the shear force's rate of change and in D.)
  SceneParams p = small_curtain(1e3);
  p.damping = 0;
  p.families.on[static_cast<int>(SpringFamily::shear)] = false;
  const Scene scene(p);
  const double T = 0.2;
  for (const auto& [method, order] : {std::pair{"rattle", 2.0}, std::pair{"fast_projection", 1.0}}) {
    CAPTURE(method);
    const Vector fine = run(scene, method, T / 3200, 3200);
    const double e1 = largest_distance(run(scene, method, T / 100, 100), fine);
    const double e2 = largest_distance(run(scene, method, T / 200, 200), fine);
    const double observed = std::log2(e1 / e2);
    CAPTURE(e1);
    CAPTURE(e2);
    CHECK(observed == doctest::Approx(order).epsilon(0.15));
  }
}

TEST_CASE("the inextensible curtain converges to the spring model's motion at first order in 1/K") {
  // The stretch the structural constraints forbid is the load over K (Chapter 10), the load being the weight and
  // the flexion springs' push when the sheet bends; with the flexion stiffness fixed, the positions differ by
  // O(1/K): ten times the stiffness, a tenth of the distance.
  const double T = 0.1;
  std::vector<double> distance;
  for (const double K : {1e5, 1e6}) {
    SceneParams p = small_curtain(K);
    p.flexion_stiffness = 1e3;
    const Scene scene(p);
    const double h_rk4 = 1.0 / std::sqrt(24 * K / p.mass);  // h omega_max <= 1
    const int n_rk4 = static_cast<int>(std::ceil(T / h_rk4));
    const Vector springs = run(scene, "rk4", T / n_rk4, n_rk4);
    const Vector constrained = run(scene, "rattle", T / 2000, 2000);
    distance.push_back(largest_distance(springs, constrained));
  }
  CAPTURE(distance[0]);
  CAPTURE(distance[1]);
  CHECK(std::log10(distance[0] / distance[1]) == doctest::Approx(1.0).epsilon(0.2));
}
