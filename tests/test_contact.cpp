// Contact with obstacles (Chapter 11) against closed forms: a sheet on an inclined plane sticks when
// tan(theta) <= mu_s and otherwise slides with acceleration g (sin theta - mu_k cos theta); no particle ever ends
// an accepted step inside the plane; the signed distances are those of the geometry.
#include "base/input_error.hpp"
#include "contact/obstacles.hpp"
#include "integrators/contact_implicit_euler.hpp"
#include "integrators/contact_stepper.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "model/fabric.hpp"

#include "flat_sheet.hpp"

#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

using namespace cloth;

namespace {

constexpr double g = 9.81;
constexpr double thickness = 0.005;

// The plane through the origin whose downhill direction is (cos theta, 0, -sin theta).
Eigen::Vector3d incline_normal(double theta) { return {std::sin(theta), 0.0, std::cos(theta)}; }
Eigen::Vector3d downhill(double theta) { return {std::cos(theta), 0.0, -std::sin(theta)}; }

// A 10 x 10 sheet, 2 cm spacing, 0.2 kg/m^2, no pins, at rest on the plane (its centres one thickness above it).
SceneParams sheet_on_incline(double theta) {
  SceneParams p;
  p.grid = Grid{10, 10, 0.02};
  p.mass = particle_mass(0.2, p.grid.d);
  p.stiffness = 10.0;  // omega_max = sqrt(10.125 K / m) = 1125 /s: symplectic Euler is stable below h = 1.78 ms
  p.damping = 0.0;
  p.pins = PinSet::none;
  p.initial_velocity_z = 0.0;
  p.gravity = g;
  p.orientation = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
  p.origin = thickness * incline_normal(theta);
  return p;
}

ContactModel incline(double theta, double mu_s, double mu_k) {
  ContactModel model;
  model.obstacles.emplace_back(HalfSpace{Eigen::Vector3d::Zero(), incline_normal(theta)});
  model.thickness = thickness;
  model.friction = {mu_s, mu_k};
  return model;
}

struct InclineRun {
  double mean_downhill_velocity;  // of the sheet at T
  double largest_displacement;    // of any particle from its start, at T
  double deepest;                 // largest penetration thickness - phi after any step
};

// The name the tests give Baraff and Witkin's implicit Euler with contact filtered inside CG.
constexpr const char* filtered = "filtered implicit_euler";

// `method` from the registry wrapped in the contact correction, or Baraff and Witkin's filtered step.
std::unique_ptr<Stepper> contact_stepper(const std::string& method, ForceField& field, const ContactModel& model) {
  if (method == filtered) return std::make_unique<ContactImplicitEuler>(field, model);
  return std::make_unique<ContactStepper>(make_stepper(method, field), model);
}

// Runs the sheet for T with `method` and contact, checking every accepted step.
InclineRun run_incline(const std::string& method, double theta, double mu_s, double mu_k, double h, double T) {
  const Scene scene(sheet_on_incline(theta));
  ForceField field(scene);
  const ContactModel model = incline(theta, mu_s, mu_k);
  const std::unique_ptr<Stepper> stepper = contact_stepper(method, field, model);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  const Vector x_start = x;
  double deepest = -1;
  const auto steps = static_cast<int>(std::lround(T / h));
  for (int k = 0; k < steps; ++k) {
    REQUIRE(stepper->step(h, x, v));
    deepest = std::max(deepest, deepest_penetration(model, x));
  }
  double mean = 0, largest = 0;
  for (int s = 0; s < scene.free_count(); ++s) {
    mean += v.segment<3>(3 * s).dot(downhill(theta));
    largest = std::max(largest, (x - x_start).segment<3>(3 * s).norm());
  }
  return {mean / scene.free_count(), largest, deepest};
}

}  // namespace

TEST_CASE("signed distances: a plane's is the height above it, a sphere's the distance to its surface") {
  const Obstacle ground = HalfSpace{Eigen::Vector3d(0, 0, -0.5), Eigen::Vector3d::UnitZ()};
  const SurfacePoint above = surface_point(ground, Eigen::Vector3d(3, -2, 0.25));
  CHECK(above.phi == doctest::Approx(0.75).epsilon(1e-15));
  CHECK(above.normal == Eigen::Vector3d::UnitZ());
  const Obstacle ball = Sphere{Eigen::Vector3d(1, 2, 3), 0.3};
  const SurfacePoint inside = surface_point(ball, Eigen::Vector3d(1, 2, 3.1));
  CHECK(inside.phi == doctest::Approx(-0.2).epsilon(1e-14));
  CHECK((inside.normal - Eigen::Vector3d::UnitZ()).norm() < 1e-15);
  const SurfacePoint out = surface_point(ball, Eigen::Vector3d(1 + 0.6, 2 + 0.8, 3));  // 1 m from the centre
  CHECK(out.phi == doctest::Approx(0.7).epsilon(1e-14));
  CHECK((out.normal - Eigen::Vector3d(0.6, 0.8, 0)).norm() < 1e-15);
}

TEST_CASE("frictionless contact stops the normal velocity only: tangential motion and leaving velocities kept") {
  ContactModel model;
  model.obstacles.emplace_back(HalfSpace{});
  model.thickness = 0.01;
  Vector x0(6), x1(6), v1(6);
  x0 << 0, 0, 0.02, 1, 1, 0.005;
  x1 << 0.1, 0, 0.004, 1, 1, 0.006;  // the first arrives 6 mm deep in the shell, the second leaves it
  v1 << 2, -1, -3, 0.5, 0, 0.4;
  CHECK(resolve_obstacle_contacts(model, x0, x1, v1) == 2);
  CHECK(x1[2] == doctest::Approx(0.01).epsilon(1e-14));  // put back on the shell's surface
  CHECK(x1[0] == doctest::Approx(0.1).epsilon(1e-14));   // the tangential displacement kept
  CHECK(v1.head<3>() == Eigen::Vector3d(2, -1, 0));
  CHECK(x1[5] == doctest::Approx(0.01).epsilon(1e-14));
  CHECK(v1.tail<3>() == Eigen::Vector3d(0.5, 0, 0.4));   // already leaving: untouched
}

// Chapter 11's Exercise 1: symplectic Euler moves a resting particle h^2 g into the shell and the correction returns
// it to rest where it was; explicit Euler does not move it, so the contact is seen a step late and its velocity
// alternates between -h g and 0 while it stays on the shell.
TEST_CASE("a particle resting on the ground: symplectic Euler's step corrected to rest, explicit Euler's a step late") {
  const Scene scene(cloth_test::flat_sheet(thickness, 0));  // at rest on the shell, under the default gravity g
  const ContactModel ground = incline(0.0, 0.3, 0.2);
  const double h = 1e-3;
  for (const char* method : {"symplectic_euler", "explicit_euler"}) {
    CAPTURE(method);
    ForceField field(scene);
    ContactStepper stepper(make_stepper(method, field), ground);
    Vector x = scene.initial_positions(), v = scene.initial_velocities();
    for (int k = 1; k <= 4; ++k) {
      REQUIRE(stepper.step(h, x, v));
      const bool late = std::string(method) == "explicit_euler" && k % 2 == 1;
      CHECK(stepper.last_contacts() == (late ? 0 : scene.free_count()));
      for (int s = 0; s < scene.free_count(); ++s) {
        CHECK(x[3 * s + 2] == doctest::Approx(thickness).epsilon(1e-12));
        CHECK(v[3 * s + 2] == doctest::Approx(late ? -h * g : 0.0).epsilon(1e-12));
      }
    }
  }
}

TEST_CASE("a scene placed on the incline rests one thickness above it; a placement that is not a rotation is refused") {
  const Scene scene(sheet_on_incline(0.4));
  const Vector x = scene.initial_positions();
  for (int s = 0; s < scene.free_count(); ++s)
    CHECK(incline_normal(0.4).dot(x.segment<3>(3 * s)) == doctest::Approx(thickness).epsilon(1e-12));
  SceneParams p = sheet_on_incline(0.4);
  p.orientation(0, 0) *= 2;
  CHECK_THROWS_AS(Scene{p}, InputError);
}

TEST_CASE("contact models out of range are refused with a line saying what is accepted") {
  ContactModel model;
  model.friction = {0.2, 0.3};
  CHECK_THROWS_WITH_AS(validate(model), "mu_k = 0.3: expected a finite number in [0, mu_s = 0.2]", InputError);
  model = {};
  model.thickness = 0;
  CHECK_THROWS_AS(validate(model), InputError);
  model = {};
  model.obstacles.emplace_back(HalfSpace{Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 2)});
  CHECK_THROWS_AS(validate(model), InputError);
}

TEST_CASE("a sheet on an incline slides with g (sin theta - mu_k cos theta) past the cone (each family)") {
  // theta = 30 degrees, mu_s = 0.3, mu_k = 0.2: a = 9.81 (0.5 - 0.2 cos 30) = 3.206 m/s^2; T = 0.5 s, so the
  // sheet slides 0.4 m, twice its own width.
  const double theta = std::numbers::pi / 6, mu_s = 0.3, mu_k = 0.2, T = 0.5;
  const double a = g * (std::sin(theta) - mu_k * std::cos(theta));
  for (const char* method : {"symplectic_euler", "rk4", "implicit_euler", "xpbd", "small_steps", filtered}) {
    CAPTURE(method);
    const InclineRun run = run_incline(method, theta, mu_s, mu_k, 1e-3, T);
    CHECK(run.mean_downhill_velocity / T == doctest::Approx(a).epsilon(0.01));
    CHECK(run.deepest <= 0.01 * thickness);
  }
}

TEST_CASE("the sheet sticks for tan theta <= mu_s and slides just past it: the edge of the static cone") {
  const double mu_s = 0.5, mu_k = 0.4, T = 0.25, h = 1e-3;
  // Just inside the cone it does not move; frictionless it would slide g sin(theta) T^2 / 2 = 0.14 m.
  const double inside = std::atan(0.999 * mu_s);
  // Just outside it slides with the kinetic coefficient: a = g (sin - mu_k cos) = 0.88 m/s^2.
  const double outside = std::atan(1.001 * mu_s);
  const double a = g * (std::sin(outside) - mu_k * std::cos(outside));
  for (const char* method : {"symplectic_euler", "small_steps", filtered}) {
    CAPTURE(method);
    const InclineRun held = run_incline(method, inside, mu_s, mu_k, h, T);
    CHECK(held.largest_displacement < 1e-9 * (0.5 * g * std::sin(inside) * T * T));
    CHECK(std::abs(held.mean_downhill_velocity) < 1e-12);
    CHECK(held.deepest <= 0.01 * thickness);
    const InclineRun slid = run_incline(method, outside, mu_s, mu_k, h, T);
    CHECK(slid.mean_downhill_velocity / T == doctest::Approx(a).epsilon(0.01));
    CHECK(slid.deepest <= 0.01 * thickness);
  }
}

TEST_CASE("the contact wrapper runs in the driver: it counts the inner method's work and keeps its name") {
  const Scene scene(sheet_on_incline(0.3));
  ForceField field(scene);
  ContactStepper stepper(make_stepper("rk4", field), incline(0.3, 0.1, 0.1));
  RunSettings settings;
  settings.dt = 1e-3;
  settings.t_end = 0.1;
  settings.frames = 2;
  const RunResult result = simulate(stepper, settings);
  CHECK(result.status == RunStatus::ok);
  CHECK(stepper.name() == "rk4");
  CHECK(result.counters.steps == 100);
  CHECK(result.counters.rhs_evaluations == 400);
  CHECK(stepper.last_contacts() == scene.free_count());
}

TEST_CASE("filtered implicit Euler: contacts enter as the sheet lands and leave when it is thrown up") {
  // A free 10 x 10 sheet 2 cm above the ground (its shell 1.5 cm clear), falling, then resting: no particle
  // ever inside the shell, and once landed every particle constrained.
  SceneParams p = sheet_on_incline(0.0);
  p.origin = Eigen::Vector3d(0, 0, 0.02);
  p.damping = 0.01;
  const Scene scene(p);
  ForceField field(scene);
  ContactModel ground = incline(0.0, 0.5, 0.4);
  ContactImplicitEuler stepper(field, ground);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  const double h = 1e-3;
  for (int k = 0; k < 200; ++k) {  // 0.2 s: it lands at t = sqrt(2 0.015 / g) = 0.055 s
    REQUIRE(stepper.step(h, x, v));
    CHECK(deepest_penetration(ground, x) <= 0.01 * thickness);
  }
  CHECK(stepper.constrained() == scene.free_count());
  CHECK(v.cwiseAbs().maxCoeff() < 1e-9);  // at rest on the ground
  // Thrown up at 1 m/s, it leaves at once (no constraint holds a particle moving away) and flies as implicit
  // Euler flies a free particle: v_k = 1 - k h g, so after 100 steps z = thickness + 100 h - g h^2 100 101 / 2.
  for (int s = 0; s < scene.free_count(); ++s) v[3 * s + 2] = 1.0;
  for (int k = 0; k < 100; ++k) REQUIRE(stepper.step(h, x, v));
  CHECK(stepper.constrained() == 0);
  double mean_z = 0;
  for (int s = 0; s < scene.free_count(); ++s) mean_z += x[3 * s + 2] / scene.free_count();
  CHECK(mean_z == doctest::Approx(thickness + 100 * h - g * h * h * 5050).epsilon(1e-9));
}

TEST_CASE("a sheet dropped on a sphere on the ground: no particle ends an accepted step inside either, each family") {
  // An 8 x 8 sheet of 5 cm spacing, 0.2 kg/m^2, falling flat from 2 cm above a 15 cm sphere under its centre: its
  // middle lands on the sphere after 64 ms and its edges fold down around it.
  SceneParams p;
  p.grid = Grid{8, 8, 0.05};
  p.mass = particle_mass(0.2, p.grid.d);
  p.stiffness = 50.0;
  p.damping = 0.01;
  p.pins = PinSet::none;
  p.initial_velocity_z = 0.0;
  const double r = 0.15, cx = 3.5 * p.grid.d;
  p.origin = Eigen::Vector3d(0, 0, 2 * r + 0.02 + thickness);
  const Scene scene(p);
  ContactModel model;
  model.obstacles.emplace_back(HalfSpace{});
  model.obstacles.emplace_back(Sphere{Eigen::Vector3d(cx, cx, r), r});
  model.thickness = thickness;
  model.friction = {0.3, 0.2};
  for (const char* method : {"symplectic_euler", "rk4", "implicit_euler", "sdirk2", "bdf2", "local_global", "xpbd",
                             "small_steps", filtered}) {
    CAPTURE(method);
    ForceField field(scene);
    const std::unique_ptr<Stepper> stepper = contact_stepper(method, field, model);
    Vector x = scene.initial_positions(), v = scene.initial_velocities();
    double deepest = -1, lowest_centre = 1;
    for (int k = 0; k < 400; ++k) {  // 0.2 s
      REQUIRE(stepper->step(5e-4, x, v));
      deepest = std::max(deepest, deepest_penetration(model, x));
    }
    for (int s = 0; s < scene.free_count(); ++s) lowest_centre = std::min(lowest_centre, x[3 * s + 2]);
    CHECK(deepest <= 0.01 * thickness);
    // The motion is real: free fall alone would have taken the sheet 0.2 m down, through the sphere's top.
    CHECK(lowest_centre < 2 * r);
  }
}
